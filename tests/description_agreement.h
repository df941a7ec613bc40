#pragma once
// The checks every device's description test runs (tests/<device>/description_test.cpp):
// the description (stream/device_description.h), the API's .proto messages (read through
// the protobuf descriptor, not through our code) and the end-of-run summary agree.

#include "stream/device_description.h"

#include <gtest/gtest.h>

#include <google/protobuf/descriptor.h>
#include <google/protobuf/descriptor.pb.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

namespace rs4sim::testing {

// Every counter of the description is a uint64 field of `message` (repeated exactly when it
// has several values), and every field of `message` is a counter of the description.
template <typename Device, typename Counters>
void expect_counters_agree(const stream::DeviceDescription<Device, Counters>& d,
                           const google::protobuf::Descriptor& message) {
  EXPECT_EQ(message.name(), d.counters_message);
  std::set<std::string> described;
  for (const auto& c : d.counters) {
    SCOPED_TRACE(std::string(c.name));
    EXPECT_TRUE(described.insert(std::string(c.name)).second) << "named twice";
    const auto* field = message.FindFieldByName(std::string(c.name));
    ASSERT_NE(field, nullptr) << "not a field of " << message.full_name();
    EXPECT_EQ(field->cpp_type(), google::protobuf::FieldDescriptor::CPPTYPE_UINT64);
    EXPECT_EQ(field->is_repeated(), c.size > 1);
  }
  for (int i = 0; i < message.field_count(); ++i) {
    EXPECT_TRUE(described.count(message.field(i)->name()) == 1)
        << message.field(i)->name() << " of " << message.full_name()
        << " is not in the description";
  }
}

// "bad-checksum" for METRON_FAULT_BAD_CHECKSUM: the enum value's name after `prefix`, in
// lower case, '_' as '-'.
inline std::string fault_word(const std::string& value_name, const std::string& prefix) {
  std::string word = value_name.substr(prefix.size());
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char ch) {
    return ch == '_' ? '-' : static_cast<char>(std::tolower(ch));
  });
  return word;
}

// The description's faults are the fault enum's values (UNSPECIFIED and deprecated aliases
// aside), in the enum's order.
template <typename Device, typename Counters>
void expect_faults_agree(const stream::DeviceDescription<Device, Counters>& d,
                         const google::protobuf::EnumDescriptor& faults,
                         const std::string& prefix) {
  std::vector<std::string> words;
  for (int i = 0; i < faults.value_count(); ++i) {
    const auto* v = faults.value(i);
    if (v->number() == 0 || v->options().deprecated()) continue;
    words.push_back(fault_word(v->name(), prefix));
  }
  std::vector<std::string> described;
  for (const auto& f : d.faults) described.emplace_back(f.name);
  EXPECT_EQ(described, words);
}

// Both of the above: the description against the API's Counters message and fault enum.
template <typename Device, typename Counters>
void expect_description_agrees(const stream::DeviceDescription<Device, Counters>& d,
                               const google::protobuf::Descriptor& counters,
                               const google::protobuf::EnumDescriptor& faults,
                               const std::string& fault_prefix) {
  {
    SCOPED_TRACE("counters");
    expect_counters_agree(d, counters);
  }
  SCOPED_TRACE("faults");
  expect_faults_agree(d, faults, fault_prefix);
}

}  // namespace rs4sim::testing
