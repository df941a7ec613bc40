#pragma once
// The command line's words for a usage error (README "Using it": a specific message, exit 2).
// CLI11's own texts ("Check memroy value in {memory->0,...} OR {0,1,2,3} FAILED", "The
// following arguments were not expected") are replaced here through CLI11's own hooks: a
// Validator per fixed list of values, and App::failure_message for what the parser refuses,
// each naming the valid words and, for a near miss, the word meant.

#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rs4sim::app {

// The Levenshtein distance (insert, delete, substitute one character).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, when it is a near miss: at most 2 edits and fewer than a
// third of the longer word's characters, or `word` a prefix of exactly one candidate; the
// first one on a tie. Case is ignored.
[[nodiscard]] std::optional<std::string> did_you_mean(std::string_view word,
                                                      const std::vector<std::string>& candidates);

// "a, b or c".
[[nodiscard]] std::string word_list(const std::vector<std::string>& words);

// "'memroy' is not a link; use memory, pty, serial or udp (did you mean 'memory'?)".
[[nodiscard]] std::string not_one_of(std::string_view value, std::string_view what,
                                     const std::vector<std::string>& words);

// A Validator for a fixed list of words (`what`: "a link", "a device"); the help shows them.
[[nodiscard]] CLI::Validator one_of(std::string what, std::vector<std::string> words);

// The same as a transformer into the value's number in `words` (an enum option: CLI11 reads
// the number): "pty" → "1" for {memory, pty, serial, udp}.
[[nodiscard]] CLI::Validator one_of_index(std::string what, std::vector<std::string> words);

// App::failure_message for the top-level App: "rs4sim run: unknown option --adress (did you
// mean --address?); rs4sim run --help lists the options" for words the parser left over,
// "rs4sim run: --link: ..." for the rest, each with the command it belongs to.
[[nodiscard]] std::string usage_failure(const CLI::App* top, const CLI::Error& e);

// "rs4sim: unknown command 'rnu' (did you mean 'run'?); the commands are ...".
[[nodiscard]] std::string unknown_command(std::string_view word,
                                          const std::vector<std::string>& commands);

}  // namespace rs4sim::app
