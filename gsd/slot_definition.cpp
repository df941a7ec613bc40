// SlotDefinition … EndSlotDefinition ([PROFIBUS GSD spec SlotDefinition]):
//   Slot(n) = "name" default allowed
// `default` is the reference number (the bare number line of a Module block) of the module the
// slot holds unless the user chooses another; `allowed` is a range `1-4` or a list `1,3,5` of
// reference numbers. A slot the interpreter cannot read is left out with a warning: the
// station still has its modules (docs/gsd.md "The rule").
#include "gsd/interp_detail.h"

#include <algorithm>
#include <set>
#include <unordered_map>

namespace rs4sim::gsd::detail {
namespace {

using References = std::unordered_map<std::uint32_t, const Module*>;

Result<std::vector<std::uint32_t>> allowed_refs(const std::string& file,
                                                const syntax::Statement& st,
                                                const References& refs) {
  const syntax::Field& f = st.fields[2];
  std::vector<std::uint32_t> out;
  if (f.size() == 1 && f[0].is_range()) {
    for (const auto& [ref, m] : refs) {
      if (ref >= f[0].number && ref <= f[0].high) out.push_back(ref);
    }
  } else {
    for (const auto& v : f) {
      if (!v.is_number()) return error(file, st, GsdError::kBadValue, "allowed: numbers expected");
      if (v.number >= 0 && refs.count(static_cast<std::uint32_t>(v.number))) {
        out.push_back(static_cast<std::uint32_t>(v.number));
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

Result<SlotDef> read_slot(const std::string& file, const syntax::Statement& st,
                          const References& refs) {
  if (!st.is("Slot")) {
    return error(file, st, GsdError::kBadValue,
                 "SlotDefinition holds only Slot(n) = \"name\" default allowed lines");
  }
  RS4SIM_GSD_TRY(const auto number, number_arg(file, st, 0, 255));
  if (!st.has_equals || st.fields.size() != 3 || st.fields[0].size() != 1 ||
      !st.fields[0][0].is_string() || st.fields[1].size() != 1 || !st.fields[1][0].is_number()) {
    return error(file, st, GsdError::kBadValue, "Slot expects (n) = \"name\" default allowed");
  }
  SlotDef slot{static_cast<int>(number), st.fields[0][0].text, 0, {}, st.line};
  const std::int64_t def = st.fields[1][0].number;
  if (def < 0 || !refs.count(static_cast<std::uint32_t>(def))) {
    return error(file, st, GsdError::kUnknownReference,
                 "Slot(" + std::to_string(number) + "): no module has the reference number " +
                     std::to_string(def));
  }
  slot.default_ref = static_cast<std::uint32_t>(def);
  RS4SIM_GSD_TRY(slot.allowed, allowed_refs(file, st, refs));
  if (!std::binary_search(slot.allowed.begin(), slot.allowed.end(), slot.default_ref)) {
    slot.allowed.insert(
        std::upper_bound(slot.allowed.begin(), slot.allowed.end(), slot.default_ref),
        slot.default_ref);
  }
  return slot;
}

}  // namespace

Result<std::vector<SlotDef>> interpret_slots(const std::string& file, const syntax::Entry& entry,
                                             const std::vector<Module>& modules,
                                             std::vector<Warning>& warnings) {
  References refs;
  for (const auto& m : modules) {
    if (m.reference) refs.emplace(*m.reference, &m);  // the first module of a number
  }
  std::vector<SlotDef> slots;
  std::set<int> numbers;
  for (const auto& st : *entry.body) {
    auto slot = read_slot(file, st, refs);
    if (!slot) {
      RS4SIM_GSD_TRYV(forgive(warnings, std::move(slot).error()));
    } else if (!numbers.insert(slot.value().number).second) {
      warn(warnings, file, st,
           "Slot(" + std::to_string(slot.value().number) + ") given twice; line ignored");
    } else {
      slots.push_back(std::move(slot).value());
    }
  }
  std::sort(slots.begin(), slots.end(),
            [](const SlotDef& a, const SlotDef& b) { return a.number < b.number; });
  return slots;
}

}  // namespace rs4sim::gsd::detail
