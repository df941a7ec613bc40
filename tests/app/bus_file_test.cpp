// parse_bus_file (app/devices/bus_file.h) on bad input: every refusal is a UsageError (the CLI
// exits 2) naming the bus file, where (the JSON path, or line:column for a syntax error) and
// why. The GSD files are the project's own corpus (tests/gsd/corpus).
#include "app/devices/bus_file.h"

#include "app/runtime/usage_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::app {
namespace {

const std::string kDir = RS4SIM_GSD_CORPUS;

// The UsageError's message, or "accepted".
std::string refusal(const std::string& text) {
  try {
    (void)parse_bus_file(text, "bus.json", kDir, "1.5M");
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(BusFile, AGoodFileIsAcceptedWithItsStationsInOrder) {
  const BusFile bus = parse_bus_file(
      R"({"stations": [{"address": 6, "gsd": "depart_moteur_fr.gsf"},
                       {"address": 7, "ident": "0x1234", "cfg": "10 20"}]})",
      "bus.json", kDir, "1.5M");
  ASSERT_EQ(bus.stations.size(), 2U);
  EXPECT_EQ(bus.stations[0].path, "$.stations[0]");
  EXPECT_EQ(bus.stations[0].device, "generic");
  EXPECT_EQ(bus.stations[0].options.gsd, kDir + "/depart_moteur_fr.gsf");
  EXPECT_EQ(bus.stations[1].options.address, 7);
}

TEST(BusFile, AMissingGsdFileNamesTheEntryAndTheFile) {
  EXPECT_EQ(refusal(R"({"stations": [{"address": 6, "gsd": "depart_moteur_fr.gsf"},
                                     {"address": 5, "gsd": "missing.gse"}]})"),
            "bus.json: $.stations[1].gsd: no file " + kDir + "/missing.gse");
}

TEST(BusFile, DeepNestingIsRefusedBeforeProtobufParsesIt) {
  // {"stations": is offsets 0-11 (the object is depth 0), a space at 12, the first '[' at 13
  // opens depth 1, the 101st '[' at 113 depth 101: column 114.
  const std::string deep = "{\"stations\": " + std::string(50'000, '[') +
                           std::string(50'000, ']') + "}";
  EXPECT_EQ(refusal(deep), "bus.json:1:114: not valid JSON: nested deeper than 100");
}

TEST(BusFile, ASyntaxErrorNamesTheLineAndColumn) {
  // Line 3, column 17: the '"' where a ',' or '}' must follow "address": 5.
  EXPECT_EQ(refusal("{\"stations\": [\n"
                    "  {\"address\": 6, \"gsd\": \"depart_moteur_fr.gsf\"},\n"
                    "  {\"address\": 5 \"device\": \"rs4\"}\n"
                    "]}\n"),
            "bus.json:3:17: not valid JSON: expected ',' or '}' after an object member");
  EXPECT_EQ(refusal("{\"stations\": [\n  {\"address\" 5}\n]}"),
            "bus.json:2:14: not valid JSON: expected ':' after the key");
  EXPECT_EQ(refusal("{\"stations\": [\n  {5: 5}\n]}"),
            "bus.json:2:4: not valid JSON: expected a key in double quotes");
  EXPECT_EQ(refusal("{\"stations\": [{\"address\": 5}]}\n}"),
            "bus.json:2:1: not valid JSON: text after the end of the JSON value");
  EXPECT_EQ(refusal("{\"stations\": [{\"device\": \"rs4"),
            "bus.json:1:26: not valid JSON: a string without its closing quote");
  EXPECT_EQ(refusal(""),
            "bus.json:1:1: not valid JSON: expected a value, found the end of the text");
  // Deep nesting is refused, not a stack overflow.
  EXPECT_EQ(refusal(std::string(1000, '[')),
            "bus.json:1:102: not valid JSON: nested deeper than 100");
}

TEST(BusFile, AWrongValueTypeNamesTheJsonPathAndWhatWasGiven) {
  EXPECT_EQ(refusal(R"({"stations": [{"address": "5", "device": "rs4"}]})"),
            "bus.json: $.stations[0].address: expected an integer, got a string");
  // 126 is the delivery address: no slave in operation has it, as for `run --address`
  EXPECT_EQ(refusal(R"({"stations": [{"address": 126, "device": "rs4"}]})"),
            "bus.json: $.stations[0].address: 126 is outside 0..125");
  EXPECT_EQ(refusal(R"({"stations": [{"address": 5.5, "device": "rs4"}]})"),
            "bus.json: $.stations[0].address: expected an integer, got 5.5");
  EXPECT_EQ(refusal(R"({"stations": [{"address": 1e300, "device": "rs4"}]})"),
            "bus.json: $.stations[0].address: 1e+300 is outside 0..125");
  EXPECT_EQ(refusal(R"({"stations": [{"address": 5, "gsd": "depart_moteur_fr.gsf",
                                      "modules": "Relay 8"}]})"),
            "bus.json: $.stations[0].modules: expected an array of strings, got a string");
  EXPECT_EQ(refusal(R"({"stations": [{"address": 5, "device": ["rs4"]}]})"),
            "bus.json: $.stations[0].device: expected a string, got an array");
  EXPECT_EQ(refusal(R"({"stations": [5]})"),
            "bus.json: $.stations[0]: expected an object, got a number");
  EXPECT_EQ(refusal(R"({"stations": {}})"),
            "bus.json: $.stations: expected a non-empty array of stations");
}

TEST(BusFile, AnUnknownKeyIsNamedWithTheKeysAStationTakes) {
  const std::string e = refusal(R"({"stations": [{"address": 5, "device": "rs4", "adress": 6}]})");
  EXPECT_EQ(e.rfind("bus.json: $.stations[0].adress: unknown key (a station takes: address, ", 0),
            0U)
      << e;
  EXPECT_EQ(refusal(R"({"stations": [{"address": 5, "device": "rs4"}], "master": 2})"),
            "bus.json: $.master: unknown key (the bus file takes: stations)");
  // A key that is not a plain word is named as a JSON string, never as an empty place.
  EXPECT_EQ(refusal(R"({"stations": [{"address": 5, "device": "rs4"}], "": 2})"),
            R"(bus.json: $[""]: unknown key (the bus file takes: stations))");
}

TEST(BusFile, AnAddressTwiceNamesBothEntries) {
  EXPECT_EQ(refusal(R"({"stations": [{"address": 6, "gsd": "depart_moteur_fr.gsf"},
                                     {"address": 7, "ident": "0x1234", "cfg": "10"},
                                     {"address": 6, "device": "rs4"}]})"),
            "bus.json: $.stations[2].address: 6 is already used by $.stations[0]");
}

}  // namespace
}  // namespace rs4sim::app
