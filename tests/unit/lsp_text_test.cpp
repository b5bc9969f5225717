// Where the words of a line are (nc_tokens), file URIs and UTF-16 columns (documents).
#include <gtest/gtest.h>

#include "lsp/documents.hpp"
#include "lsp/nc_tokens.hpp"

using namespace ncvm::lsp;
using K = Token::Kind;

TEST(LspTokens, ReadsAddressesVariablesKeywordsAndComments) {
  const auto t = tokenizeLine("N10 G01X-1.5 #101=#5021 (CUT) IF[#1GT2]GOTO 20 <SUB1>");
  ASSERT_GE(t.size(), 10u);
  EXPECT_EQ(t[0].kind, K::Address);
  EXPECT_EQ(t[0].letter, 'N');
  EXPECT_EQ(t[0].value, "10");
  EXPECT_EQ(t[1].letter, 'G');
  EXPECT_EQ(t[1].value, "01");
  EXPECT_EQ(t[2].letter, 'X');
  EXPECT_EQ(t[2].value, "-1.5");
  EXPECT_EQ(t[2].begin, 7u);
  EXPECT_EQ(t[2].end, 12u);
  EXPECT_EQ(t[3].kind, K::Variable);
  EXPECT_EQ(t[3].value, "101");
  bool comment = false, gt = false, target = false, name = false;
  for (const auto& x : t) {
    comment |= x.kind == K::Comment;
    gt |= x.kind == K::Keyword && x.value == "GT";
    target |= x.kind == K::GotoTarget && x.value == "20";
    name |= x.kind == K::ProgramName && x.value == "SUB1";
    EXPECT_FALSE(x.kind == K::Address && x.letter == 'U') << "no address inside (CUT)";
  }
  EXPECT_TRUE(comment && gt && target && name);
}

TEST(LspTokens, FindsTheWordAtOrJustBeforeTheCursor) {
  EXPECT_EQ(tokenAt("G01 X10.", 5)->letter, 'X');
  EXPECT_EQ(tokenAt("G01 X10.", 3)->letter, 'G');  // just after G01
  EXPECT_FALSE(tokenAt("G01   X10.", 4));
  EXPECT_EQ(tokenAt("GOTO#1", 4)->kind, K::Variable);  // a computed GOTO has no target
  EXPECT_EQ(integerValue("0100"), 100);
  EXPECT_FALSE(integerValue("1.5"));
  EXPECT_FALSE(integerValue(""));
}

TEST(LspDocuments, ConvertsFileUrisBothWays) {
  EXPECT_EQ(uriToPath("file:///tmp/a%20b/c.nc"), "/tmp/a b/c.nc");
  EXPECT_EQ(uriToPath("file://localhost/x.nc"), "/x.nc");
  EXPECT_EQ(uriToPath("untitled:Untitled-1"), "");
  EXPECT_EQ(pathToUri("/tmp/a b/c#1.nc"), "file:///tmp/a%20b/c%231.nc");
  EXPECT_EQ(uriToPath(pathToUri("/x/\xc3\xa9t\xc3\xa9.nc")), "/x/\xc3\xa9t\xc3\xa9.nc");
}

TEST(LspDocuments, CountsColumnsInUtf16) {
  const std::string line = "(\xc3\xa9\xf0\x9f\x94\xa7) X1";  // (é🔧) X1
  EXPECT_EQ(utf16Column(line, 1), 1);
  EXPECT_EQ(utf16Column(line, 3), 2);  // after é (2 bytes, 1 unit)
  EXPECT_EQ(utf16Column(line, 7), 4);  // after the wrench (4 bytes, 2 units)
  EXPECT_EQ(byteColumn(line, 4), 7u);
  EXPECT_EQ(byteColumn(line, 6), 9u);  // X
}

TEST(LspDocuments, KeepsTheTextOfOpenDocumentsAndSplitsLines) {
  DocumentStore docs;
  docs.open("file:///p.nc", "O1\r\nG00\n", 1);
  ASSERT_TRUE(docs.change("file:///p.nc", "O2\r\nG01\r\n", 2));
  EXPECT_FALSE(docs.change("file:///q.nc", "", 1));
  const Document* d = docs.find("file:///p.nc");
  EXPECT_EQ(d->path, "/p.nc");
  EXPECT_EQ(d->version, 2);
  EXPECT_EQ(d->line(1), "G01");
  EXPECT_EQ(d->lines().size(), 3u);
  docs.close("file:///p.nc");
  EXPECT_FALSE(docs.find("file:///p.nc"));
}
