#include "tools/cli.h"

#include <cstdio>
#include <memory>
#include <vector>

namespace tools {
namespace {

// CLI11's help layout with the command's own synopsis and description first.
class CommandFormatter : public CLI::Formatter {
 public:
  CommandFormatter(std::string usage, std::string description)
      : usage_(std::move(usage)), description_(std::move(description)) {
    column_width(24);
  }
  std::string make_description(const CLI::App*) const override {
    return usage_ + (description_.empty() ? "" : "\n") + description_;
  }
  std::string make_usage(const CLI::App*, std::string) const override { return {}; }
  // The option's value as a word (--out DIR); what it needs or excludes is said in its text.
  std::string make_option_opts(const CLI::Option* option) const override {
    if (!option->nonpositional() || option->get_type_size() == 0) return {};
    return " " + option->get_type_name();
  }
  std::string make_option_desc(const CLI::Option* option) const override {
    std::string text = option->get_description();
    if (!option->get_default_str().empty()) text += " (default " + option->get_default_str() + ")";
    if (option->get_required()) text += " (required)";
    return text;
  }
  const std::string& usage() const { return usage_; }

 private:
  std::string usage_, description_;
};

// The sub-command the parser stopped in ("tamponade mesh" -> its "check").
const CLI::App& innermostCommand(const CLI::App& app) {
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  return *command;
}

// "tamponade mesh check": the names from the top app down to `command`.
std::string commandPath(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* parent = command.get_parent(); parent != nullptr;
       parent = parent->get_parent())
    path = parent->get_name() + " " + path;
  return path;
}

// What CLI11's ExtrasError says, with the words in the order they were given.
std::string unexpectedArguments(const CLI::App& app) {
  for (const CLI::App* command = &innermostCommand(app); command != nullptr;
       command = command->get_parent()) {
    const std::vector<std::string> words = command->remaining();
    if (words.empty()) continue;
    std::string text = words.size() > 1 ? "The following arguments were not expected:"
                                        : "The following argument was not expected:";
    for (const std::string& word : words) text += " " + word;
    return text;
  }
  return "unexpected arguments";
}

}  // namespace

void describeCommand(CLI::App& app, const std::string& usage, const std::string& description,
                     const std::string& footer) {
  app.formatter(std::make_shared<CommandFormatter>(usage, description));
  app.set_help_flag("-h,--help", "print this help and exit");
  if (!footer.empty()) app.footer(footer);
}

CLI::App* addSubcommand(CLI::App& parent, const std::string& name, const std::string& summary,
                        const std::string& usage, const std::string& description,
                        const std::string& footer) {
  CLI::App* sub = parent.add_subcommand(name, summary);
  describeCommand(*sub, usage, description, footer);
  return sub;
}

std::optional<int> parseCommandLine(CLI::App& app, Args args) {
  std::vector<std::string> words(args.rbegin(), args.rend());  // CLI11 takes them reversed
  try {
    app.parse(words);
    return std::nullopt;
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::ExtrasError&) {
    return usageError(innermostCommand(app), unexpectedArguments(app));
  } catch (const CLI::ParseError& e) {
    return usageError(innermostCommand(app), e.what());
  }
}

int usageError(const CLI::App& app, const std::string& problem) {
  const std::string path = commandPath(app);
  const auto formatter = std::dynamic_pointer_cast<const CommandFormatter>(app.get_formatter());
  std::fprintf(stderr, "%s: %s\n\n%s(%s --help explains every option)\n", path.c_str(),
               problem.c_str(), formatter ? formatter->usage().c_str() : "", path.c_str());
  return 2;
}

}  // namespace tools
