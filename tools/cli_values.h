// The checks and conversions of option values that several `tamponade` commands share, as CLI11
// validators: CLI11 prefixes each message with the option's name ("--threads: '0' must be a
// positive whole number").
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tools {

// A whole number from 1 to `max` ("abc", "12x", "0" and values beyond `max` are refused).
CLI::Validator positiveInteger(long max = std::numeric_limits<long>::max());

// A whole number from `min` to `max`.
CLI::Validator wholeNumber(long min, long max);

// A finite number > 0 and at most `max`.
CLI::Validator positiveNumber(double max = std::numeric_limits<double>::infinity());

// A number from `min` to `max`, both included.
CLI::Validator numberBetween(double min, double max);

// One of `names`; the message lists them ("'x' must be draft, standard or fine").
CLI::Validator oneOf(std::vector<std::string> names);

// "a, b or c".
std::string wordList(const std::vector<std::string>& words, const char* last = "or");

// A memory size with its unit, "512 MiB", "8GiB", "2 GB", as bytes; nullopt for anything else (a
// bare number is refused: MB and MiB differ by 5 %).
std::optional<double> parseMemorySize(const std::string& text);

// parseMemorySize as a CLI11 transform: the option's text becomes the number of bytes.
CLI::Validator memorySize();

}  // namespace tools
