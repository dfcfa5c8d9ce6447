// The relative links of README.md and docs/*.md point at files of the repository and at headings that
// exist; the checker itself finds a missing file, a missing heading and a link out of the repository.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "tests/docs/markdown_links.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using motostab::docs_test::MarkdownLink;
using motostab::docs_test::calcHeadingSlug;
using motostab::docs_test::checkLink;
using motostab::docs_test::readRelativeLinks;

// Every broken relative link of `files`, as "file:line: target: reason".
std::vector<std::string> findBrokenLinks(const std::vector<fs::path>& files, const fs::path& root, int& count) {
  std::vector<std::string> broken;
  count = 0;
  for (const auto& f : files)
    for (const MarkdownLink& link : readRelativeLinks(f)) {
      ++count;
      const std::string why = checkLink(link, root);
      if (!why.empty())
        broken.push_back(fs::relative(f, root).string() + ":" + std::to_string(link.line) + ": " + link.target + ": " + why);
    }
  return broken;
}

TEST(DocsLinks, ReadmeAndDocsHaveNoBrokenRelativeLink) {
  const fs::path root(MOTOSTAB_SOURCE_DIR);
  std::vector<fs::path> files{root / "README.md"};
  std::vector<fs::path> docs;
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") docs.push_back(e.path());
  std::sort(docs.begin(), docs.end());
  files.insert(files.end(), docs.begin(), docs.end());
  int count = 0;
  const auto broken = findBrokenLinks(files, root, count);
  for (const auto& b : broken) ADD_FAILURE() << b;
  std::printf("%zu files, %d relative links, %zu broken\n", files.size(), count, broken.size());
  EXPECT_GT(count, 20);  // the checker reads links at all
}

// GitHub's slugs: lower case, punctuation dropped, spaces to '-'.
TEST(DocsLinks, HeadingSlugsFollowGitHub) {
  EXPECT_EQ(calcHeadingSlug("Output files"), "output-files");
  EXPECT_EQ(calcHeadingSlug("`steer_controller`"), "steer_controller");
  EXPECT_EQ(calcHeadingSlug("Speed x roll maps (turns)"), "speed-x-roll-maps-turns");
  EXPECT_EQ(calcHeadingSlug("A, B and C: 1.5 m/s"), "a-b-and-c-15-ms");
}

TEST(DocsLinks, FindsMissingFilesHeadingsAndLinksOutOfTheTree) {
  const fs::path root = makeTempDir("docs_links");
  fs::create_directories(root / "docs");
  std::ofstream(root / "docs" / "b.md") << "# Title\n\n## Output files\n\n## Output files\n";
  std::ofstream(root / "outside.md") << "# Out\n";
  std::ofstream(root / "docs" / "a.md")
      << "# A\n[good](b.md#output-files) [second](b.md#output-files-1) [self](#a) ![img](b.md)\n"
      << "[web](https://example.org/x.md) `[code](missing.md)`\n```\n[fenced](missing.md)\n```\n"
      << "[gone](missing.md)\n[no heading](b.md#nothing)\n[out](../outside.md)\n";
  int count = 0;
  const auto broken = findBrokenLinks({root / "docs" / "a.md"}, root / "docs", count);
  EXPECT_EQ(count, 7);
  ASSERT_EQ(broken.size(), 3u);
  EXPECT_EQ(broken[0], "a.md:7: missing.md: no such file");
  EXPECT_EQ(broken[1], "a.md:8: b.md#nothing: no heading #nothing");
  EXPECT_EQ(broken[2], "a.md:9: ../outside.md: outside the repository");
}

}  // namespace
