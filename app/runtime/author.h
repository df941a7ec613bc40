#pragma once
// Who is making a change and from which computer, as the archive records it with every
// version (docs/storage.md "What maintenance records"): the user is --user when given, else
// the OS user (the effective uid's login name, then $USER); the host is the machine's name.

#include "storage/types.h"

#include <string>

namespace rs4sim::app {

[[nodiscard]] std::string os_user();
[[nodiscard]] std::string host_name();
// `user_option` is --user ("" when not given).
[[nodiscard]] storage::Author local_author(const std::string& user_option);

}  // namespace rs4sim::app
