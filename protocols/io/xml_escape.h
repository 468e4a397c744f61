// Escaping of text placed in XML or HTML (XDMF sidecars, the HTML report, SVG charts).
#pragma once

#include <string>
#include <string_view>

namespace protocols {

// & < > " ' as entities. The apostrophe becomes &#39; (valid in XML and every HTML version;
// &apos; is not HTML 4), so one function serves the XDMF files and the report alike.
std::string escapeXml(std::string_view text);

}  // namespace protocols
