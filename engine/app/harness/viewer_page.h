// The step-through viewer's page and the equation table it links to, built into the program
// from engine/app/harness/viewer/index.html and docs/the-text.md (embed_page.cmake writes
// viewer_page.cpp at build time), so the page needs nothing beside it but its data and frames.
#pragma once

#include <string>

namespace lamina::tutorial {

// index.html: the page, its script and styles inline.
std::string viewer_page_html();

// {"3-16": "statement", ...}: each equation of the text with its statement, as docs/the-text.md
// states it in its table "Every numbered equation".
std::string equation_table_json();

}  // namespace lamina::tutorial
