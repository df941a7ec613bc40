// The command line's words for a usage error (app/runtime/cli_words.h): the edit distance, the
// near miss it suggests, the list of valid values, and CLI11's refusals rewritten through its
// own hooks (Validator, App::failure_message).
#include "app/runtime/cli_words.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rs4sim::app {
namespace {

TEST(EditDistance, CountsInsertDeleteSubstituteAndANeighbourSwapAsOneEach) {
  EXPECT_EQ(edit_distance("address", "address"), 0U);
  EXPECT_EQ(edit_distance("adress", "address"), 1U);  // one letter left out
  EXPECT_EQ(edit_distance("memroy", "memory"), 1U);   // two neighbours swapped
  EXPECT_EQ(edit_distance("pty", "udp"), 3U);         // every letter differs
  EXPECT_EQ(edit_distance("", "udp"), 3U);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3U);  // the textbook example
}

TEST(DidYouMean, SuggestsANearMissOnlyAndTheClosestOne) {
  const std::vector<std::string> links{"memory", "pty", "serial", "udp"};
  EXPECT_EQ(did_you_mean("memroy", links), "memory");
  EXPECT_EQ(did_you_mean("serail", links), "serial");
  EXPECT_EQ(did_you_mean("PTY", links), "pty");         // case is ignored
  EXPECT_EQ(did_you_mean("can", links), std::nullopt);  // nothing near
  EXPECT_EQ(did_you_mean("tcp", links), std::nullopt);  // 2 edits from udp: a 3-letter word allows 1
  const std::vector<std::string> options{"--address", "--device", "--duration", "--link"};
  EXPECT_EQ(did_you_mean("--adress", options), "--address");
  EXPECT_EQ(did_you_mean("--dur", options), "--duration");  // a prefix of one option only
  EXPECT_EQ(did_you_mean("--d", options), std::nullopt);    // too short to say
  EXPECT_EQ(did_you_mean("--bogus", options), std::nullopt);
}

TEST(NotOneOf, NamesTheValidWordsAndTheNearMiss) {
  const std::vector<std::string> links{"memory", "pty", "serial", "udp"};
  EXPECT_EQ(not_one_of("memroy", "a link", links),
            "'memroy' is not a link; use memory, pty, serial or udp (did you mean 'memory'?)");
  EXPECT_EQ(not_one_of("can", "a link", links),
            "'can' is not a link; use memory, pty, serial or udp");
  EXPECT_EQ(word_list({"on", "off"}), "on or off");
  EXPECT_EQ(word_list({"on"}), "on");
}

// CLI11's own parser with the hooks in place, as main() sets them up.
struct Parsed {
  int exit = 0;
  std::string err;
};
Parsed parse(std::vector<std::string> words) {
  CLI::App top{"rs4sim"};
  top.failure_message(usage_failure);
  top.require_subcommand(1);
  CLI::App* run = top.add_subcommand("run", "");
  int address = 0;
  int link = -1;
  run->add_option("--address", address);
  run->add_option("--link", link)->transform(one_of_index("a link", {"memory", "pty"}));
  std::vector<const char*> argv{"rs4sim"};
  for (const auto& w : words) argv.push_back(w.c_str());
  std::ostringstream out, err;
  Parsed p;
  try {
    top.parse(static_cast<int>(argv.size()), argv.data());
    p.exit = link;  // the transformer's number reached the option
  } catch (const CLI::ParseError& e) {
    p.exit = top.exit(e, out, err);
  }
  p.err = err.str();
  return p;
}

TEST(UsageFailure, AnUnknownOptionIsNamedWithTheOneMeantAndItsValueIsNotAnotherError) {
  const Parsed p = parse({"run", "--adress", "4"});
  EXPECT_NE(p.exit, 0);
  EXPECT_EQ(p.err,
            "rs4sim run: unknown option --adress (did you mean --address?)\n"
            "rs4sim run --help lists its options\n");
}

TEST(UsageFailure, AValueOutsideTheListNamesTheListAndTheNearMiss) {
  const Parsed p = parse({"run", "--link", "ptty"});
  EXPECT_EQ(p.err,
            "rs4sim run: --link: 'ptty' is not a link; use memory or pty (did you mean 'pty'?)\n"
            "rs4sim run --help lists its options\n");
  EXPECT_EQ(parse({"run", "--link", "pty"}).exit, 1);  // "pty" → LinkKind 1
}

TEST(UsageFailure, AStrayWordIsAnUnexpectedArgument) {
  const Parsed p = parse({"run", "extra"});
  EXPECT_EQ(p.err,
            "rs4sim run: unexpected argument 'extra'\nrs4sim run --help lists its options\n");
}

TEST(UnknownCommand, SuggestsTheCommandMeant) {
  EXPECT_EQ(unknown_command("rnu", {"demo", "master", "run"}),
            "rs4sim: unknown command 'rnu' (did you mean 'run'?); the commands are demo, master, "
            "run (rs4sim --help)");
  EXPECT_EQ(unknown_command("frobnicate", {"demo", "run"}),
            "rs4sim: unknown command 'frobnicate'; the commands are demo, run (rs4sim --help)");
}

}  // namespace
}  // namespace rs4sim::app
