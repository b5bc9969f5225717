#pragma once
// Field-by-field comparison of compiled programs for the loader's tests: the fast line path
// and the chunked reader must give exactly the general compiler's Program.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "lang/ir.hpp"

namespace ncvm::test {

inline uint64_t bits(double v) {
  return std::bit_cast<uint64_t>(v);
}

inline void expectSameLoc(const SourceLoc& a, const SourceLoc& b, const std::string& what) {
  EXPECT_EQ(a.file, b.file) << what;
  EXPECT_EQ(a.line, b.line) << what;
  EXPECT_EQ(a.col, b.col) << what;
}

inline void expectSameAlarms(const std::vector<Alarm>& a, const std::vector<Alarm>& b,
                             const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].code, b[k].code) << what << " alarm " << k;
    EXPECT_EQ(a[k].text, b[k].text) << what << " alarm " << k;
    expectSameLoc(a[k].loc, b[k].loc, what + " alarm " + std::to_string(k));
    EXPECT_EQ(a[k].n, b[k].n) << what << " alarm " << k;
    EXPECT_EQ(a[k].program, b[k].program) << what << " alarm " << k;
  }
}

// Every field of two compiled programs.
inline void expectSamePrograms(const Program& a, const Program& b, const std::string& text) {
  EXPECT_EQ(a.number, b.number);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.label, b.label);
  expectSameLoc(a.loc, b.loc, "program");
  ASSERT_EQ(a.blocks.size(), b.blocks.size()) << text;
  for (size_t k = 0; k < a.blocks.size(); ++k) {
    const Block &x = a.blocks[k], &y = b.blocks[k];
    std::string what = "block " + std::to_string(k) + " (line " + std::to_string(x.loc.line) + ")";
    EXPECT_EQ(x.kind, y.kind) << what;
    EXPECT_EQ(x.skipLevel, y.skipLevel) << what;
    EXPECT_EQ(x.loopId, y.loopId) << what;
    EXPECT_EQ(x.flags, y.flags) << what;
    EXPECT_EQ(x.nWords, y.nWords) << what;
    EXPECT_EQ(x.firstWord, y.firstWord) << what;
    expectSameLoc(x.loc, y.loc, what);
    EXPECT_EQ(x.n, y.n) << what;
    EXPECT_EQ(x.comment, y.comment) << what;
    EXPECT_EQ(a.loopParent(k), b.loopParent(k)) << what;
    EXPECT_EQ(x.ops, y.ops) << what;
  }
  ASSERT_EQ(a.words.size(), b.words.size());
  for (size_t k = 0; k < a.words.size(); ++k) {
    const Word &x = a.words[k], &y = b.words[k];
    std::string what = "word " + std::to_string(k);
    EXPECT_EQ(x.letter, y.letter) << what;
    EXPECT_EQ(x.kind, y.kind) << what;
    EXPECT_EQ(x.flags, y.flags) << what;
    EXPECT_EQ(x.col, y.col) << what;
    if (x.kind == WordKind::Literal)
      EXPECT_EQ(bits(x.value), bits(y.value)) << what << ": " << x.value << " " << y.value;
    else
      EXPECT_EQ(x.a, y.a) << what;
  }
  ASSERT_EQ(a.macroOps.size(), b.macroOps.size());
  for (size_t k = 0; k < a.macroOps.size(); ++k) {
    const MacroOps &x = a.macroOps[k], &y = b.macroOps[k];
    EXPECT_EQ(x.cond, y.cond);
    EXPECT_EQ(x.lhsVar, y.lhsVar);
    EXPECT_EQ(x.lhsExpr, y.lhsExpr);
    EXPECT_EQ(x.rhs, y.rhs);
    EXPECT_EQ(x.gotoLabel, y.gotoLabel);
    EXPECT_EQ(x.gotoExpr, y.gotoExpr);
    EXPECT_EQ(x.target, y.target);
    EXPECT_EQ(x.thenAssign, y.thenAssign);
    EXPECT_EQ(x.printKind, y.printKind);
    EXPECT_EQ(x.firstPrint, y.firstPrint);
    EXPECT_EQ(x.nPrint, y.nPrint);
    EXPECT_EQ(x.error, y.error);
  }
  ASSERT_EQ(a.code.size(), b.code.size());
  for (size_t k = 0; k < a.code.size(); ++k) {
    EXPECT_EQ(a.code[k].op, b.code[k].op);
    EXPECT_EQ(a.code[k].fn, b.code[k].fn);
    EXPECT_EQ(a.code[k].col, b.code[k].col);
    EXPECT_EQ(a.code[k].arg, b.code[k].arg);
  }
  ASSERT_EQ(a.consts.size(), b.consts.size());
  for (size_t k = 0; k < a.consts.size(); ++k) EXPECT_EQ(bits(a.consts[k]), bits(b.consts[k]));
  ASSERT_EQ(a.exprs.size(), b.exprs.size());
  for (size_t k = 0; k < a.exprs.size(); ++k) {
    EXPECT_EQ(a.exprs[k].begin, b.exprs[k].begin);
    EXPECT_EQ(a.exprs[k].end, b.exprs[k].end);
  }
  ASSERT_EQ(a.prints.size(), b.prints.size());
  for (size_t k = 0; k < a.prints.size(); ++k) {
    EXPECT_EQ(a.prints[k].isVar, b.prints[k].isVar);
    EXPECT_EQ(a.prints[k].text, b.prints[k].text);
    EXPECT_EQ(a.prints[k].expr, b.prints[k].expr);
    EXPECT_EQ(a.prints[k].intDigits, b.prints[k].intDigits);
    EXPECT_EQ(a.prints[k].fracDigits, b.prints[k].fracDigits);
  }
  EXPECT_EQ(a.strings, b.strings);
  expectSameAlarms(a.errors, b.errors, "errors");
  expectSameAlarms(a.structural, b.structural, "structural");
  EXPECT_EQ(a.lostLoops, b.lostLoops);
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_EQ(a.loopParents, b.loopParents);
}

}  // namespace ncvm::test
