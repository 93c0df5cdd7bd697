#include "motoflex/report/markdown_html.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "motoflex/report/html_text.hpp"

namespace motoflex::report {
namespace {

std::string trim(std::string_view text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && (text[begin] == ' ' || text[begin] == '\t' || text[begin] == '\r')) {
    ++begin;
  }
  while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r')) {
    --end;
  }
  return std::string(text.substr(begin, end - begin));
}

// Escapes `text` and turns `code` and **bold** into markup.
std::string inline_markup(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '`') {
      const std::size_t close = text.find('`', i + 1);
      if (close != std::string_view::npos) {
        out += "<code>" + escape_html(text.substr(i + 1, close - i - 1)) + "</code>";
        i = close + 1;
        continue;
      }
    }
    if (text.substr(i, 2) == "**") {
      const std::size_t close = text.find("**", i + 2);
      if (close != std::string_view::npos) {
        out += "<strong>" + inline_markup(text.substr(i + 2, close - i - 2)) + "</strong>";
        i = close + 2;
        continue;
      }
    }
    out += escape_html(text.substr(i, 1));
    ++i;
  }
  return out;
}

std::vector<std::string> table_cells(const std::string& line) {
  std::string row = trim(line);
  if (!row.empty() && row.front() == '|') row.erase(0, 1);
  if (!row.empty() && row.back() == '|') row.pop_back();
  std::vector<std::string> cells;
  std::string cell;
  for (const char c : row) {
    if (c == '|') {
      cells.push_back(trim(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(trim(cell));
  return cells;
}

bool is_separator_row(const std::string& line) {
  for (const char c : line) {
    if (c != '|' && c != '-' && c != ':' && c != ' ') return false;
  }
  return line.find('-') != std::string::npos;
}

std::string image_html(const std::string& line, const std::string& image_dir) {
  // ![alt](file)
  const std::size_t close_alt = line.find("](");
  const std::size_t close = line.rfind(')');
  const std::string alt = line.substr(2, close_alt - 2);
  const std::string file = line.substr(close_alt + 2, close - close_alt - 2);
  const std::string uri = png_data_uri((std::filesystem::path(image_dir) / file).string());
  if (uri.empty()) {
    return "<p class=\"note\">(image " + escape_html(file) + ": not available)</p>\n";
  }
  return "<figure><img src=\"" + uri + "\" alt=\"" + escape_html(alt) + "\"><figcaption>" +
         escape_html(alt) + "</figcaption></figure>\n";
}

bool is_image_line(const std::string& line) {
  return line.rfind("![", 0) == 0 && line.find("](") != std::string::npos && line.back() == ')';
}

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string png_data_uri(const std::string& path, std::size_t max_bytes) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (error || size > max_bytes || size < 8) return "";
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.rfind("\x89PNG\r\n\x1a\n", 0) != 0) return "";
  return "data:image/png;base64," + base64(bytes);
}

std::string markdown_to_html(std::string_view markdown, const std::string& image_dir,
                             int heading_offset) {
  std::vector<std::string> lines;
  {
    std::istringstream in{std::string(markdown)};
    std::string line;
    while (std::getline(in, line)) lines.push_back(trim(line));
  }
  std::string html;
  std::string paragraph;
  auto flush_paragraph = [&] {
    if (!paragraph.empty()) html += "<p>" + inline_markup(paragraph) + "</p>\n";
    paragraph.clear();
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.empty()) {
      flush_paragraph();
      continue;
    }
    if (line.front() == '#') {
      flush_paragraph();
      std::size_t level = 0;
      while (level < line.size() && line[level] == '#') ++level;
      const int shown = std::min<int>(6, static_cast<int>(level) + heading_offset);
      const std::string tag = "h" + std::to_string(shown);
      html += "<" + tag + ">" + inline_markup(trim(line.substr(level))) + "</" + tag + ">\n";
      continue;
    }
    if (line.front() == '|' && i + 1 < lines.size() && is_separator_row(lines[i + 1])) {
      flush_paragraph();
      html += "<table><thead><tr>";
      for (const auto& cell : table_cells(line)) html += "<th>" + inline_markup(cell) + "</th>";
      html += "</tr></thead><tbody>\n";
      i += 2;
      for (; i < lines.size() && !lines[i].empty() && lines[i].front() == '|'; ++i) {
        html += "<tr>";
        for (const auto& cell : table_cells(lines[i])) {
          html += "<td>" + inline_markup(cell) + "</td>";
        }
        html += "</tr>\n";
      }
      --i;
      html += "</tbody></table>\n";
      continue;
    }
    if (is_image_line(line)) {
      flush_paragraph();
      html += image_html(line, image_dir);
      continue;
    }
    paragraph += (paragraph.empty() ? "" : " ") + line;
  }
  flush_paragraph();
  return html;
}

}  // namespace motoflex::report
