// Markdown subset → self-contained HTML for REPORT.html (see report_html.hpp).
#include "molchaos/validation/report_html.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace molchaos::validation {

std::string base64(const std::string& bytes) {
  static constexpr char k_alphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t k) {
      return k < bytes.size() ? static_cast<unsigned>(static_cast<unsigned char>(bytes[k])) : 0u;
    };
    const unsigned triple = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += k_alphabet[triple >> 18 & 63];
    out += k_alphabet[triple >> 12 & 63];
    out += i + 1 < bytes.size() ? k_alphabet[triple >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? k_alphabet[triple & 63] : '=';
  }
  return out;
}

namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

// `code`, **bold** and *italic*. An asterisk opens emphasis only at the start of a word and
// closes it only at its end, so products such as a2*b stay as they are.
std::string inline_html(const std::string& text) {
  std::string out;
  bool bold = false, italic = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char prev = i > 0 ? text[i - 1] : ' ';
    if (text[i] == '`') {
      const auto end = text.find('`', i + 1);
      if (end != std::string::npos) {
        out += "<code>" + escape(text.substr(i + 1, end - i - 1)) + "</code>";
        i = end;
        continue;
      }
    }
    if (text.compare(i, 2, "**") == 0 && (bold || (!word_char(prev) && i + 2 < text.size()))) {
      out += bold ? "</strong>" : "<strong>";
      bold = !bold;
      ++i;
      continue;
    }
    if (text[i] == '*') {
      const char next = i + 1 < text.size() ? text[i + 1] : ' ';
      if (!italic && !word_char(prev) && next != ' ') {
        out += "<em>";
        italic = true;
        continue;
      }
      if (italic && !word_char(next) && prev != ' ') {
        out += "</em>";
        italic = false;
        continue;
      }
    }
    out += escape(std::string(1, text[i]));
  }
  if (italic) out += "</em>";
  if (bold) out += "</strong>";
  return out;
}

std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|') {
      const auto a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

std::string slug(const std::string& heading) {
  std::string out;
  for (char c : heading) {
    if (word_char(c))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.empty() ? "section" : out;
}

std::string image_html(const std::string& line, const std::string& directory) {
  const auto close_alt = line.find("](");
  const std::string alt = line.substr(2, close_alt - 2);
  const std::string file = line.substr(close_alt + 2, line.rfind(')') - close_alt - 2);
  const auto path = std::filesystem::path(directory) / file;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("report_html: cannot read figure " + path.string());
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string type = file.ends_with(".gif") ? "gif" : "png";
  return "<figure><img alt=\"" + escape(alt) + "\" src=\"data:image/" + type + ";base64," +
         base64(bytes.str()) + "\"></figure>\n";
}

constexpr const char* k_style =
    "body{font-family:'DejaVu Sans',sans-serif;max-width:72em;margin:2em auto;padding:0 1em;"
    "line-height:1.45;color:#111}table{border-collapse:collapse;margin:1em 0;font-size:0.9em}"
    "th,td{border:1px solid #bbb;padding:0.25em 0.5em;vertical-align:top}th{background:#eee}"
    "img{max-width:100%;height:auto}figure{margin:1em 0}code{background:#f3f3f3;padding:0 0.2em}"
    "pre{background:#f3f3f3;padding:0.6em;overflow-x:auto}nav{font-size:0.9em}";

// The body: one pass over the lines, holding at most one open block (paragraph, table, list).
std::string body_html(const std::string& markdown, const std::string& directory,
                      std::vector<std::pair<std::string, std::string>>& sections) {
  std::istringstream in(markdown);
  std::string line, out, open;  // open: "p", "table", "ul" or ""
  int table_row = 0;
  bool code = false;
  const auto close = [&] {
    if (!open.empty()) out += "</" + open + ">\n";
    open.clear();
  };
  while (std::getline(in, line)) {
    if (line.starts_with("```")) {
      close();
      out += code ? "</pre>\n" : "<pre>";
      code = !code;
    } else if (code) {
      out += escape(line) + "\n";
    } else if (line.starts_with("# ")) {
      close();
      out += "<h1>" + inline_html(line.substr(2)) + "</h1>\n<!--toc-->\n";
    } else if (line.starts_with("## ")) {
      close();
      const std::string title = line.substr(3);
      sections.emplace_back(slug(title), title);
      out += "<h2 id=\"" + sections.back().first + "\">" + inline_html(title) + "</h2>\n";
    } else if (line.starts_with("![")) {
      close();
      out += image_html(line, directory);
    } else if (line.starts_with("|")) {
      if (open != "table") {
        close();
        out += "<table>\n";
        open = "table";
        table_row = 0;
      }
      if (table_row++ == 1) continue;  // the |---| separator
      const char* cell = table_row == 1 ? "th" : "td";
      out += "<tr>";
      for (const auto& c : table_cells(line))
        out += std::string("<") + cell + ">" + inline_html(c) + "</" + cell + ">";
      out += "</tr>\n";
    } else if (line.starts_with("- ")) {
      if (open != "ul") {
        close();
        out += "<ul>\n";
        open = "ul";
      }
      out += "<li>" + inline_html(line.substr(2)) + "</li>\n";
    } else if (line.empty()) {
      close();
    } else {
      if (open != "p") {
        close();
        out += "<p>";
        open = "p";
      } else {
        out += "\n";
      }
      out += inline_html(line);
    }
  }
  close();
  if (code) out += "</pre>\n";
  return out;
}

}  // namespace

std::string report_html(const std::string& markdown, const std::string& image_directory) {
  std::vector<std::pair<std::string, std::string>> sections;
  std::string body = body_html(markdown, image_directory, sections);
  std::string toc = "<nav><strong>Contents:</strong>";
  for (std::size_t k = 0; k < sections.size(); ++k)
    toc += std::string(k ? " · " : " ") + "<a href=\"#" + sections[k].first + "\">" +
           inline_html(sections[k].second) + "</a>";
  toc += "</nav>\n";
  const auto marker = body.find("<!--toc-->");
  if (marker != std::string::npos) body.replace(marker, 10, toc);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>molchaos: reproduction report</title>\n<style>" +
         std::string(k_style) + "</style>\n</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace molchaos::validation
