// The RS4's description (rs4/device/description.h): its faults are the names the API's
// DeviceState.faults_present gives, the injectable ones are rs4sim.v1.Fault's values (read
// through the protobuf descriptor), and its option checks (moved here from the app) fill the
// manual's defaults and refuse with the same sentences as before.
#include "rs4/device/description.h"

#include "rs4sim/v1/rs4.pb.h"

#include <gtest/gtest.h>

#include <google/protobuf/descriptor.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <string>
#include <vector>

namespace rs4sim::rs4::device {
namespace {

std::vector<std::string> fault_names() {
  std::vector<std::string> out;
  for (const auto& f : description().faults) out.emplace_back(f.name);
  return out;
}

TEST(Rs4Description, FaultsAreTheScannersEight) {
  // docs/rs4-scanner.md "Faults": the project's eight, by their API names.
  EXPECT_EQ(fault_names(),
            (std::vector<std::string>{"ossd_cross_circuit", "motor_speed", "internal_hardware",
                                      "dazzled", "window_contaminated", "field_pair_sequence",
                                      "field_pair_invalid", "unknown_command"}));
}

TEST(Rs4Description, EveryInjectableFaultOfTheApiIsDescribed) {
  const auto names = fault_names();
  const auto& e = *v1::Fault_descriptor();
  for (int i = 0; i < e.value_count(); ++i) {
    if (e.value(i)->number() == 0) continue;
    std::string word = e.value(i)->name().substr(std::string("FAULT_").size());
    std::transform(word.begin(), word.end(), word.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    EXPECT_NE(std::find(names.begin(), names.end(), word), names.end()) << word;
  }
}

TEST(Rs4Description, NoCountersAndNoCountersMessage) {
  EXPECT_TRUE(description().counters.empty());
  EXPECT_TRUE(description().counters_message.empty());
  EXPECT_EQ(description().kind, stream::DeviceKind::kRs4);
  EXPECT_EQ(description().link, stream::LinkKind::kProfibusDp);
}

TEST(Rs4RunOptions, DefaultsAreTheManuals) {
  RunOptions o;
  EXPECT_EQ(check_run_options(o), "");
  EXPECT_EQ(o.addresses, std::vector<int>{4});  // the switches' factory setting [RS4 manual §2]
  EXPECT_EQ(o.boot_time_ms, 30000);             // [RS4 manual §1]
  EXPECT_EQ(o.command_time_ms, 40);
  EXPECT_EQ(o.response_time_ms, 10);  // "Reaktionszeit PROFIsafe-Adapter 10 ms"
}

// The refusal of the options `set` gives (the others unset).
std::string refusal(const std::function<void(RunOptions&)>& set) {
  RunOptions o;
  set(o);
  return check_run_options(o);
}

TEST(Rs4RunOptions, Refusals) {
  EXPECT_EQ(refusal([](RunOptions& o) { o.addresses = {126}; }),
            "--address: 126 is outside 0..125 (a DP slave in operation; 126 is the delivery "
            "address)");
  EXPECT_EQ(refusal([](RunOptions& o) {
              o.addresses = {4, 5, 4};
            }),
            "--address 4 given twice (each RS4 is a station of its own on the link)");
  EXPECT_EQ(refusal([](RunOptions& o) {
              o.addresses = {4};
              o.serial_numbers = {1, 2};
            }),
            "--serial-number given 2 times for 1 --address (one serial number per RS4, in the "
            "order of --address)");
  EXPECT_EQ(refusal([](RunOptions& o) { o.serial_numbers = {0}; }),
            "--serial-number: 0 is outside 1..4294967295 (the RS4's identity holds 32 bits; 0 "
            "means none)");
  EXPECT_EQ(refusal([](RunOptions& o) {
              o.addresses = {4, 5};
              o.serial_numbers = {7, 7};
            }),
            "--serial-number 7 given twice (every unit has its own)");
  EXPECT_EQ(refusal([](RunOptions& o) { o.state_files = {""}; }), "--state: an empty file name");
  EXPECT_EQ(refusal([](RunOptions& o) {
              o.addresses = {4, 5};
              o.rs232 = true;
            }),
            "--rs232 serves one RS4; run it with one --address");
  EXPECT_EQ(refusal([](RunOptions& o) { o.boot_time_ms = 600001; }),
            "--boot-time: 600001 ms is outside 0..600000");
  EXPECT_EQ(refusal([](RunOptions& o) { o.command_time_ms = -1; }),
            "--command-time: -1 ms is outside 0..120000 (the manual: the RS4 needs up to 2 "
            "minutes, [RS4 manual §5.2.1])");
  EXPECT_EQ(refusal([](RunOptions& o) { o.response_time_ms = 1001; }),
            "--adapter-response-time: 1001 ms is outside 0..1000");
  EXPECT_EQ(refusal([](RunOptions& o) { o.module = true; }),
            "--module needs --gsd FILE (the built-in GSD has one module)");
}

}  // namespace
}  // namespace rs4sim::rs4::device
