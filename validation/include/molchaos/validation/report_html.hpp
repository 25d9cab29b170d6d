// The report as one self-contained HTML page: the Markdown that report_markdown() writes,
// rendered by a small writer for the constructs the report uses (headings, paragraphs, tables,
// lists, code blocks, emphasis, images), with every figure embedded as a base64 PNG (GIF for an animation).
#pragma once

#include <string>

namespace molchaos::validation {

/// Base64 (RFC 4648, with padding) of a byte string.
std::string base64(const std::string& bytes);

/// HTML page of `markdown`; an image `![alt](file.png)` (or `.gif`) is read from `image_directory` and
/// embedded as a data URI (throws std::runtime_error naming the file if it cannot be read).
/// Second-level headings get ids and a table of contents links to them.
std::string report_html(const std::string& markdown, const std::string& image_directory);

}  // namespace molchaos::validation
