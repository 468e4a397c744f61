// The command line of every `tamponade` sub-command is parsed by CLI11: typed options, checked
// values and one --help layout. This header sets up an app the same way for every command and
// turns CLI11's outcomes into the toolkit's exit codes (0 after --help, 2 after a usage error).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>

#include "tools/commands.h"

namespace tools {

// Sets up `app` (named after the whole command, "tamponade run") for the toolkit's help layout:
// `usage` (the "usage: ..." synopsis lines) and `description` (what the command does) open the
// help, the options follow, `footer` (exit codes, documentation) closes it.
void describeCommand(CLI::App& app, const std::string& usage, const std::string& description,
                     const std::string& footer = {});

// A sub-command of `parent` ("check" of "tamponade mesh"), described as by describeCommand;
// `summary` is its line in the parent's help.
CLI::App* addSubcommand(CLI::App& parent, const std::string& name, const std::string& summary,
                        const std::string& usage, const std::string& description,
                        const std::string& footer = {});

// A sub-command as its definition returns it: its app, and what runs it once the command line
// has been parsed (the options it reads live in the closure).
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// Parses `args` (the words after the command's name). nullopt: go on and run. Otherwise the exit
// code to return: 0 after printing the help on stdout, 2 after printing a usage error (naming
// the option) and the usage lines on stderr.
std::optional<int> parseCommandLine(CLI::App& app, Args args);

// A usage problem found after parsing (two options that exclude each other, a missing file):
// printed like a parse error, naming the command and its usage; returns 2.
int usageError(const CLI::App& app, const std::string& problem);

}  // namespace tools
