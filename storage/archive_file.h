#pragma once
// The export/import file: a rs4sim.v1.ArchiveExport protobuf message
// (storage/proto/rs4sim/v1/archive.proto), in binary or in protobuf's standard JSON
// mapping (docs/storage.md "Export format"). Decoding checks syntax, then validate()s
// the meaning; an import writes nothing unless the whole file is sound.

#include "storage/errors.h"
#include "storage/parameter_archive.h"
#include "storage/snapshot.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::storage {

std::vector<std::uint8_t> encode_binary(const Snapshot& snapshot);
std::string encode_json(const Snapshot& snapshot);
// kCorruptImport (syntax or meaning) or kCrcMismatch (a blob's CRC-32).
Result<Snapshot> decode_binary(std::span<const std::uint8_t> bytes);
Result<Snapshot> decode_json(std::string_view text);

Result<std::vector<std::uint8_t>> export_binary(ParameterArchive& archive, Timestamp at);
Result<std::string> export_json(ParameterArchive& archive, Timestamp at);
Result<ImportSummary> import_binary(ParameterArchive& archive, std::span<const std::uint8_t> bytes,
                                   const ImportOptions& options = {});
Result<ImportSummary> import_json(ParameterArchive& archive, std::string_view text,
                                 const ImportOptions& options = {});

}  // namespace rs4sim::storage
