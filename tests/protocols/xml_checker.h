// A small well-formedness checker for the report's XHTML and SVG (the test must not add a
// package, so no libxml2): one root element, every start tag closed in order, attributes
// name="value" with no '<' or raw '&' in values, only the five predefined entities and
// numeric character references, comments and one leading <!DOCTYPE ...>. Returns "" when the
// text is well-formed, else "offset N: what is wrong".
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace protocols_test {

inline std::string checkXml(const std::string& text) {
  std::vector<std::string> open;
  std::size_t i = 0;
  int roots = 0;
  auto fail = [&](const std::string& what) { return "offset " + std::to_string(i) + ": " + what; };
  auto isNameChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' ||
           c == '.';
  };
  auto checkEntity = [&](std::size_t& k) -> bool {  // text[k] == '&'
    const std::size_t semi = text.find(';', k);
    if (semi == std::string::npos || semi - k > 10) return false;
    const std::string name = text.substr(k + 1, semi - k - 1);
    bool ok = name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos";
    if (!ok && name.size() > 1 && name[0] == '#') {
      ok = true;
      for (std::size_t c = 1; c < name.size(); ++c)
        ok = ok && std::isdigit(static_cast<unsigned char>(name[c]));
    }
    k = semi;
    return ok;
  };
  while (i < text.size()) {
    if (text[i] == '<') {
      if (text.compare(i, 4, "<!--") == 0) {
        const std::size_t end = text.find("-->", i);
        if (end == std::string::npos) return fail("unterminated comment");
        i = end + 3;
        continue;
      }
      if (text.compare(i, 9, "<!DOCTYPE") == 0) {
        if (roots > 0 || !open.empty()) return fail("DOCTYPE after the root element");
        const std::size_t end = text.find('>', i);
        if (end == std::string::npos) return fail("unterminated DOCTYPE");
        i = end + 1;
        continue;
      }
      const bool closing = i + 1 < text.size() && text[i + 1] == '/';
      std::size_t k = i + (closing ? 2 : 1);
      const std::size_t nameStart = k;
      while (k < text.size() && isNameChar(text[k])) ++k;
      const std::string name = text.substr(nameStart, k - nameStart);
      if (name.empty()) return fail("'<' not starting a tag (escape it as &lt;)");
      if (closing) {
        while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
        if (k >= text.size() || text[k] != '>') return fail("bad end tag </" + name);
        if (open.empty() || open.back() != name)
          return fail("</" + name + "> closes <" +
                      (open.empty() ? std::string("nothing") : open.back()) + ">");
        open.pop_back();
        i = k + 1;
        continue;
      }
      // Attributes.
      std::vector<std::string> seen;
      for (;;) {
        while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
        if (k >= text.size()) return fail("unterminated tag <" + name);
        if (text[k] == '>' || text.compare(k, 2, "/>") == 0) break;
        const std::size_t a = k;
        while (k < text.size() && isNameChar(text[k])) ++k;
        const std::string attribute = text.substr(a, k - a);
        if (attribute.empty()) return fail("bad attribute in <" + name);
        for (const auto& s : seen)
          if (s == attribute) return fail("duplicate attribute " + attribute + " in <" + name);
        seen.push_back(attribute);
        if (k + 1 >= text.size() || text[k] != '=' || (text[k + 1] != '"' && text[k + 1] != '\''))
          return fail("attribute " + attribute + " of <" + name + "> without a quoted value");
        const char quote = text[k + 1];
        k += 2;
        while (k < text.size() && text[k] != quote) {
          if (text[k] == '<') return fail("'<' in attribute " + attribute);
          if (text[k] == '&' && !checkEntity(k))
            return fail("bad entity in attribute " + attribute);
          ++k;
        }
        if (k >= text.size()) return fail("unterminated attribute " + attribute);
        ++k;
      }
      if (open.empty()) {
        if (++roots > 1) return fail("second root element <" + name + ">");
      }
      if (text[k] == '>') {
        open.push_back(name);
        i = k + 1;
      } else {
        i = k + 2;
      }
      continue;
    }
    if (text[i] == '&') {
      std::size_t k = i;
      if (!checkEntity(k)) return fail("bad entity (escape '&' as &amp;)");
      i = k + 1;
      continue;
    }
    if (open.empty() && !std::isspace(static_cast<unsigned char>(text[i])))
      return fail("text outside the root element");
    ++i;
  }
  if (!open.empty()) return fail("<" + open.back() + "> is never closed");
  if (roots != 1) return fail("no root element");
  return "";
}

}  // namespace protocols_test
