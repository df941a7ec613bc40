#pragma once
// The live-view page's files (http/page/), embedded in the binary at build time by
// http/embed_page.cmake: nothing is fetched from elsewhere, by the build or by the browser.

#include <string_view>

namespace rs4sim::http {

struct PageFile {
  std::string_view path;          // "/index.html"
  std::string_view content_type;  // "text/html; charset=utf-8"
  std::string_view body;
};

// nullptr when the page has no such file.
const PageFile* find_page_file(std::string_view path) noexcept;

}  // namespace rs4sim::http
