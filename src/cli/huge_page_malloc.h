// The process's malloc on transparent huge pages (cli/huge_page_malloc.cpp):
// called first thing in main.
#pragma once

namespace fh {

void use_huge_page_malloc();

}  // namespace fh
