// Every refusal of from_document (docs/param.md "Errors"): the code, the JSON path and a
// reason that names the limit. Each case is a small hand-written document.
#include "rs4/param_doc/parameter_document.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::param_doc {
namespace {

struct Case {
  const char* document;
  DocumentError error;
  const char* path;
  const char* reason_part;  // a piece of the reason
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.document; }

class DocumentErrors : public ::testing::TestWithParam<Case> {};

TEST_P(DocumentErrors, NamesPathAndReason) {
  const Case& c = GetParam();
  const auto result = from_document(c.document, scanner::factory_default());
  ASSERT_FALSE(result);
  EXPECT_EQ(result.issue.error, c.error) << result.issue.message();
  EXPECT_EQ(result.issue.path, c.path) << result.issue.message();
  EXPECT_NE(result.issue.reason.find(c.reason_part), std::string::npos) << result.issue.message();
  EXPECT_EQ(make_error_code(result.issue.error).category().name(), std::string("rs4.param_doc"));
}

#define DOC(body) "{\"format\":1," body "}"
#define PAIR1(contour) DOC("\"pairs\":{\"1\":{\"protective\":" contour "}}")

using E = DocumentError;

const Case kSyntaxAndKeys[] = {
    {"{", E::kSyntax, "$", "not valid JSON at 1:2: expected a key in double quotes"},
    {"", E::kSyntax, "$", "not valid JSON at 1:1: expected a value, found the end of the text"},
    {R"({"format":1} trailing)", E::kSyntax, "$",
     "not valid JSON at 1:14: text after the end of the JSON value"},
    // A hand-edited document: the break named by line and column (the comma after "format"
    // is missing, so line 3 column 3 has a key where ',' or '}' belongs).
    {"{\n  \"format\": 1\n  \"start_pair\": 2\n}", E::kSyntax, "$",
     "not valid JSON at 3:3: expected ',' or '}' after an object member"},
    {R"({"format":1,"start_pair":2,"start_pair":3})", E::kSyntax, "$", "Repeated map key"},
    {R"({"format":1,"start_pair":1e400})", E::kSyntax, "$", "range of double"},
    {"[1, 2]", E::kWrongType, "$", "expected an object, found an array"},
    {"{}", E::kMissingKey, "$.format", "required"},
    {R"({"format":2})", E::kUnsupportedFormat, "$.format", "format 1"},
    {R"({"format":"1"})", E::kWrongType, "$.format", "expected a number, found a string"},
    {DOC(R"("colour":"red")"), E::kUnknownKey, "$.colour", "allowed here: format, device"},
    {DOC(R"("passwords":["ROD4LE"])"), E::kPasswordInDocument, "$.passwords", "--password"},
    {DOC(R"("pairs":{"1":{"password":"x"}})"), E::kPasswordInDocument, "$.pairs.1.password",
     "never carries passwords"},
    {DOC(R"("device":4)"), E::kWrongType, "$.device", "expected an object"},
};
INSTANTIATE_TEST_SUITE_P(SyntaxAndKeys, DocumentErrors, ::testing::ValuesIn(kSyntaxAndKeys));

const Case kOptions[] = {
    {DOC(R"("response_time_ms":100)"), E::kOutOfRange, "$.response_time_ms", "80 + n·40"},
    {DOC(R"("response_time_ms":680)"), E::kOutOfRange, "$.response_time_ms", "outside 80..640"},
    {DOC(R"("response_time_ms":40)"), E::kOutOfRange, "$.response_time_ms", "outside 80..640"},
    {DOC(R"("response_time_ms":120.5)"), E::kWrongType, "$.response_time_ms", "not an integer"},
    {DOC(R"("response_time_ms":"80")"), E::kWrongType, "$.response_time_ms", "a number"},
    {DOC(R"("restart_mode":"manual")"), E::kOutOfRange, "$.restart_mode", "start_interlock"},
    {DOC(R"("restart_mode":1)"), E::kWrongType, "$.restart_mode", "expected a string"},
    {DOC(R"("start_pair":5)"), E::kOutOfRange, "$.start_pair", "outside 1..4"},
    {DOC(R"("start_pair":0)"), E::kOutOfRange, "$.start_pair", "outside 1..4"},
    {DOC(R"("permitted":{"5":[1]})"), E::kUnknownKey, "$.permitted.5", "\"1\" to \"4\""},
    {DOC(R"("permitted":{"1":[1,5]})"), E::kOutOfRange, "$.permitted.1[1]", "outside 1..4"},
    {DOC(R"("permitted":{"1":3})"), E::kWrongType, "$.permitted.1", "expected an array"},
    {DOC(R"("permitted":{"2":[1,3]})"), E::kInvalidSet, "$.permitted.2", "permit itself"},
    {DOC(R"("warning_output":["smoke"])"), E::kOutOfRange, "$.warning_output[0]", "smoke"},
    {DOC(R"("warning_output":"fault")"), E::kWrongType, "$.warning_output", "an array"},
    {DOC(R"("measurement":{"resolution":0})"), E::kOutOfRange, "$.measurement.resolution",
     "outside 1..255"},
    {DOC(R"("measurement":{"stop":529})"), E::kOutOfRange, "$.measurement.stop", "outside 0..528"},
    {DOC(R"("measurement":{"start":300,"stop":200})"), E::kInvalidSet, "$.measurement.start",
     "start/stop"},
    {DOC(R"("measurement":{"step":2})"), E::kUnknownKey, "$.measurement.step", "resolution"},
};
INSTANTIATE_TEST_SUITE_P(Options, DocumentErrors, ::testing::ValuesIn(kOptions));

const Case kPairs[] = {
    {DOC(R"("pairs":{"0":{}})"), E::kUnknownKey, "$.pairs.0", "field pairs"},
    {DOC(R"("pairs":{"1":[]})"), E::kWrongType, "$.pairs.1", "expected an object"},
    {DOC(R"("pairs":{"1":{"safety":{}}})"), E::kUnknownKey, "$.pairs.1.safety", "protective"},
    {PAIR1("{}"), E::kBadShape, "$.pairs.1.protective", "exactly one of"},
    {PAIR1(R"({"runs":[],"segments":[]})"), E::kBadShape, "$.pairs.1.protective", "exactly one of"},
    {PAIR1(R"({"circle":{}})"), E::kUnknownKey, "$.pairs.1.protective.circle", "sector"},
    {PAIR1(R"({"runs":[{"from":0,"to":528,"mm":4001}]})"), E::kOutOfRange,
     "$.pairs.1.protective.runs[0].mm", "outside 0..4000 mm (protective field limit"},
    {DOC(R"("pairs":{"1":{"warning":{"runs":[{"from":0,"to":0,"mm":15001}]}}})"), E::kOutOfRange,
     "$.pairs.1.warning.runs[0].mm", "outside 0..15000"},
    {PAIR1(R"({"runs":[{"from":0,"to":528}]})"), E::kMissingKey, "$.pairs.1.protective.runs[0].mm",
     "required"},
    {PAIR1(R"({"runs":[{"from":0,"to":528,"mm":1,"step":1}]})"), E::kUnknownKey,
     "$.pairs.1.protective.runs[0].step", "from, to, mm"},
    {PAIR1(R"({"runs":[{"from":10,"to":9,"mm":1}]})"), E::kOutOfRange,
     "$.pairs.1.protective.runs[0].to", "outside 10..528"},
    {PAIR1(R"({"runs":[{"from":0,"to":529,"mm":1}]})"), E::kOutOfRange,
     "$.pairs.1.protective.runs[0].to", "outside 0..528"},
    {PAIR1(R"({"runs":[{"from":0,"to":10,"mm":1},{"from":10,"to":20,"mm":2}]})"), E::kOutOfRange,
     "$.pairs.1.protective.runs[1]", "segment 10 is also in run 0"},
    {PAIR1(R"({"runs":[7]})"), E::kWrongType, "$.pairs.1.protective.runs[0]", "an object"},
    {PAIR1(R"({"segments":[1,2,3]})"), E::kOutOfRange, "$.pairs.1.protective.segments",
     "3 values, the RS4 has 529"},
    {PAIR1(R"({"runs":[]})"), E::kInvalidSet, "$.pairs.1.protective",
     "start field pair has no protective field"},
};
INSTANTIATE_TEST_SUITE_P(Pairs, DocumentErrors, ::testing::ValuesIn(kPairs));

const Case kShapes[] = {
    {PAIR1(R"({"rectangle":{"x_min_mm":-5000,"x_max_mm":5000,"y_min_mm":0,"y_max_mm":1000}})"),
     E::kContourOutOfRange, "$.pairs.1.protective.rectangle",
     "segment 14 (0.00 deg) reaches 5000 mm, beyond 0..4000 mm (protective"},
    {PAIR1(R"({"rectangle":{"x_min_mm":1000,"x_max_mm":-1000,"y_min_mm":0,"y_max_mm":1000}})"),
     E::kBadShape, "$.pairs.1.protective.rectangle", "x_min_mm < x_max_mm"},
    {PAIR1(R"({"rectangle":{"x_min_mm":0,"x_max_mm":1000,"y_min_mm":0}})"), E::kMissingKey,
     "$.pairs.1.protective.rectangle.y_max_mm", "required"},
    {PAIR1(R"({"rectangle":{"x_min_mm":0,"x_max_mm":1e7,"y_min_mm":0,"y_max_mm":1}})"),
     E::kOutOfRange, "$.pairs.1.protective.rectangle.x_max_mm", "1000000"},
    {PAIR1(R"({"polygon":[[0,0],[1000,1000]]})"), E::kBadShape, "$.pairs.1.protective.polygon",
     "at least 3 points"},
    {PAIR1(R"({"polygon":[[0,0],[1000,1000],[2000,2000]]})"), E::kBadShape,
     "$.pairs.1.protective.polygon", "no area"},
    {PAIR1(R"({"polygon":[[0,0],[1000],[0,1000]]})"), E::kBadShape,
     "$.pairs.1.protective.polygon[1]", "[x_mm, y_mm]"},
    {PAIR1(R"({"polygon":[[0,0],[1000,"a"],[0,1000]]})"), E::kWrongType,
     "$.pairs.1.protective.polygon[1][1]", "a number"},
    {PAIR1(R"({"sector":{"radius_mm":0,"from_deg":0,"to_deg":90}})"), E::kBadShape,
     "$.pairs.1.protective.sector", "radius_mm must be > 0"},
    {PAIR1(R"({"sector":{"radius_mm":1000,"from_deg":90,"to_deg":0}})"), E::kBadShape,
     "$.pairs.1.protective.sector", "from_deg <= to_deg"},
    {PAIR1(R"({"sector":{"radius_mm":4500,"from_deg":0,"to_deg":90}})"), E::kContourOutOfRange,
     "$.pairs.1.protective.sector", "segment 14 (0.00 deg) reaches 4500 mm"},
};
INSTANTIATE_TEST_SUITE_P(Shapes, DocumentErrors, ::testing::ValuesIn(kShapes));

// 50,000 levels (100 KB): refused by the linear structure scan before protobuf's parser
// (quadratic in the nesting: minutes) sees the text; the 102nd '[' is at offset 101.
TEST(DocumentErrorsDeep, NestingBeyond100IsRefusedAtOnce) {
  const auto result = from_document(std::string(50'000, '[') + std::string(50'000, ']'),
                                    scanner::factory_default());
  ASSERT_FALSE(result);
  EXPECT_EQ(result.issue.error, DocumentError::kSyntax);
  EXPECT_EQ(result.issue.message(), "$: not valid JSON at 1:102: nested deeper than 100");
}

// A key or a value of 10 MB is not repeated in full in the message.
TEST(DocumentErrorsDeep, LongKeysAndValuesAreCutInTheMessage) {
  const std::string huge(10'000'000, 'k');
  const auto key = from_document("{\"format\": 1, \"" + huge + "\": 1}", scanner::factory_default());
  ASSERT_FALSE(key);
  EXPECT_LT(key.issue.message().size(), 600u);
  const auto value = from_document("{\"format\": 1, \"restart_mode\": \"" + huge + "\"}",
                                   scanner::factory_default());
  ASSERT_FALSE(value);
  EXPECT_LT(value.issue.message().size(), 600u);
  EXPECT_NE(value.issue.message().find("(10000000 bytes)"), std::string::npos);
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
