#pragma once
// Internal helpers shared by the interpreter's files (not part of the public API).

#include "gsd/error.h"
#include "gsd/model.h"
#include "gsd/syntax.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::gsd::detail {

Error error(const std::string& file, const syntax::Statement& st, GsdError code,
            std::string message);

// What the interpreter took other than written (docs/gsd.md "The rule"): file:line, the
// statement, what was done.
void warn(std::vector<Warning>& out, const std::string& file, const syntax::Statement& st,
          std::string message);
// An error on a line the master can do without becomes a warning ("…; line ignored").
Result<void> forgive(std::vector<Warning>& out, Result<void> r);

// `keyword = n` with lo <= n <= hi.
Result<std::int64_t> number(const std::string& file, const syntax::Statement& st, std::int64_t lo,
                            std::int64_t hi);
// `keyword = "a" "b"` → "ab" (adjacent strings concatenate, as after a `\` continuation).
Result<std::string> string_value(const std::string& file, const syntax::Statement& st);
// `keyword(off) = b0,b1,…` → the bytes; every value 0..255.
Result<std::vector<std::uint8_t>> byte_list(const std::string& file, const syntax::Statement& st,
                                            const syntax::Field& field);
// The single numeric `(arg)` of a statement, lo..hi.
Result<std::int64_t> number_arg(const std::string& file, const syntax::Statement& st,
                                std::int64_t lo, std::int64_t hi);

// Collects Ext_User_Prm_Data_Const/_Ref lines of one template; finish() checks them
// against the declared length and the parameter definitions.
struct TemplateBuilder {
  std::string what;  // "global User_Prm_Data", "module \"x\""
  struct Const {
    std::size_t offset;
    std::vector<std::uint8_t> bytes;
    const syntax::Statement* st;
  };
  std::vector<Const> consts;
  std::vector<PrmRef> refs;
  std::vector<const syntax::Statement*> ref_statements;
  std::optional<std::size_t> length;  // declared length, if any
  const syntax::Statement* length_st = nullptr;

  bool empty() const { return consts.empty() && refs.empty(); }
  Result<void> add_const(const std::string& file, const syntax::Statement& st);
  Result<void> add_ref(const std::string& file, const syntax::Statement& st);
  Result<PrmTemplate> finish(const std::string& file, const std::map<int, ExtParam>& params,
                             std::optional<std::size_t> max_length) const;
};

Result<ExtParam> interpret_ext_param(const std::string& file, const syntax::Entry& entry);
Result<PrmText> interpret_prm_text(const std::string& file, const syntax::Entry& entry,
                                   std::vector<Warning>& warnings);
// Unit_Diag_Bit(n) / Unit_Diag_Not_Bit(n) = "text" (X_ keywords too); a Unit_Diag_Area block
// (Value or X_Value lines); a UnitDiagType block, its lines each forgiven on its own into
// `warnings`; Channel_Diag(n) = "text" (unit_diag.cpp).
Result<void> interpret_unit_diag_bit(const std::string& file, const syntax::Statement& st,
                                     UnitDiagTexts& out);
Result<void> interpret_unit_diag_area(const std::string& file, const syntax::Entry& entry,
                                      UnitDiagTexts& out);
Result<void> interpret_unit_diag_type(const std::string& file, const syntax::Entry& entry,
                                      UnitDiag& out, std::vector<Warning>& warnings);
Result<void> interpret_channel_diag(const std::string& file, const syntax::Statement& st,
                                    UnitDiag& out);
Result<Module> interpret_module(const std::string& file, const syntax::Entry& entry,
                                const std::map<int, ExtParam>& params);
// A SlotDefinition block (slot_definition.cpp); slots naming no module are left out with a
// warning.
Result<std::vector<SlotDef>> interpret_slots(const std::string& file, const syntax::Entry& entry,
                                             const std::vector<Module>& modules,
                                             std::vector<Warning>& warnings);

}  // namespace rs4sim::gsd::detail
