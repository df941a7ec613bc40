#include "json/message.h"

#include <google/protobuf/message.h>

namespace rs4sim::json {

google::protobuf::util::Status to_message(std::string_view text,
                                          google::protobuf::Message& message,
                                          const google::protobuf::util::JsonParseOptions& options,
                                          StructureRules rules) {
  namespace util = google::protobuf::util;
  if (const auto refused = first_structure_error(text, rules)) {
    return util::InvalidArgumentError(line_column(text, refused->offset) + ": " +
                                      refused->reason);
  }
  const auto status = util::JsonStringToMessage(
      google::protobuf::StringPiece(text.data(), text.size()), &message, options);
  const auto said = status.message();
  if (status.ok() || said.size() <= kMessageLimit) return status;
  return util::Status(status.code(), cut(std::string_view(said.data(), said.size())));
}

std::string cut(std::string_view text, std::size_t limit) {
  if (text.size() <= limit) return std::string(text);
  std::size_t keep = limit;
  // Back to the start of a UTF-8 sequence: continuation bytes are 10xxxxxx.
  while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  return std::string(text.substr(0, keep)) + "\xE2\x80\xA6 (" + std::to_string(text.size()) +
         " bytes)";
}

}  // namespace rs4sim::json
