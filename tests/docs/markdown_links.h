#pragma once
// A checker of the relative links of Markdown files: [text](target) and ![alt](target). A target must
// name an existing file or folder (relative to the linking file) inside the repository; a #anchor into a
// Markdown file must name one of its headings, slugged as GitHub does (lower case; characters other than
// letters, digits, '_', '-' and ' ' dropped; spaces to '-'; a repeated slug gets -1, -2, ...). Links with
// a scheme (http:, https:, mailto:) are skipped; fenced code blocks and inline code are not read.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace motostab::docs_test {

/// A link as written: its file, line (1-based) and target text.
struct MarkdownLink {
  std::filesystem::path file;
  int line = 0;
  std::string target;
};

/// Reads `file` line by line, calling `onLine(number, text)` for each line outside fenced code blocks.
template <class OnLine>
void forEachProseLine(const std::filesystem::path& file, const OnLine& onLine) {
  std::ifstream in(file);
  std::string line;
  bool fenced = false;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      continue;
    }
    if (!fenced) onLine(number, line);
  }
}

/// GitHub's anchor of a heading text.
inline std::string calcHeadingSlug(const std::string& heading) {
  std::string slug;
  for (unsigned char c : heading) {
    if (c >= 0x80 || std::isalnum(c) || c == '_' || c == '-') slug += static_cast<char>(c >= 0x80 ? c : std::tolower(c));
    else if (c == ' ') slug += '-';
  }
  return slug;
}

/// The anchors of every heading of a Markdown file.
inline std::set<std::string> readAnchors(const std::filesystem::path& file) {
  static const std::regex heading(R"(#{1,6}\s+(.*?)\s*#*\s*)");
  std::set<std::string> anchors;
  forEachProseLine(file, [&](int, const std::string& line) {
    std::smatch m;
    if (!std::regex_match(line, m, heading)) return;
    const std::string text = m[1].str();
    const auto first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
    const std::string base = calcHeadingSlug(first == std::string::npos ? "" : text.substr(first, last - first + 1));
    std::string candidate = base;
    for (int n = 1; anchors.count(candidate); ++n) candidate = base + "-" + std::to_string(n);
    anchors.insert(candidate);
  });
  return anchors;
}

/// The relative links of a Markdown file (those with a scheme left out).
inline std::vector<MarkdownLink> readRelativeLinks(const std::filesystem::path& file) {
  static const std::regex link(R"(!?\[(?:[^\]\\]|\\.)*\]\(([^)\s]+)(?:\s+"[^"]*")?\))");
  static const std::regex inlineCode("`[^`]*`");
  static const std::regex scheme("^[a-z]+:");
  std::vector<MarkdownLink> links;
  forEachProseLine(file, [&](int number, const std::string& line) {
    const std::string prose = std::regex_replace(line, inlineCode, "");
    for (std::sregex_iterator it(prose.begin(), prose.end(), link), end; it != end; ++it)
      if (!std::regex_search((*it)[1].str(), scheme)) links.push_back({file, number, (*it)[1].str()});
  });
  return links;
}

/// Why `link` is broken ("no such file", "outside the repository", "no heading #x"), or "" if it is not.
inline std::string checkLink(const MarkdownLink& link, const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  const auto hash = link.target.find('#');
  const std::string filePart = link.target.substr(0, hash);
  const std::string anchor = hash == std::string::npos ? "" : link.target.substr(hash + 1);
  const fs::path dest = filePart.empty() ? link.file : (link.file.parent_path() / filePart).lexically_normal();
  if (!fs::exists(dest)) return "no such file";
  const std::string rootText = fs::canonical(root).string() + "/";
  if (fs::canonical(dest).string().rfind(rootText, 0) != 0) return "outside the repository";
  if (!anchor.empty() && dest.extension() == ".md" && !readAnchors(dest).count(anchor)) return "no heading #" + anchor;
  return "";
}

}  // namespace motostab::docs_test
