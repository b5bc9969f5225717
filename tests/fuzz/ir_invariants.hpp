#pragma once
// Checks that a compiled program is self-consistent: every index the executor follows
// (words, expressions, bytecode, constants, strings, errors, jump targets, loop parents)
// stays inside its array. The fuzz targets abort on a violation, so a compiler bug that
// would make the executor read out of bounds is found at compile time already.
#include <cstdio>
#include <cstdlib>

#include "lang/ir.hpp"

namespace ncvm::fuzz {

[[noreturn]] inline void violated(const char* what, size_t block) {
  std::fprintf(stderr, "IR invariant violated: %s (block %zu)\n", what, block);
  std::abort();
}

inline void checkProgram(const Program& p) {
  const size_t nb = p.blocks.size();
  auto expr = [&](int32_t e, size_t k) {
    if (e < 0) return;
    if (static_cast<size_t>(e) >= p.exprs.size()) violated("expression index", k);
    const ExprRange& r = p.exprs[static_cast<size_t>(e)];
    if (r.begin > r.end || r.end > p.code.size()) violated("expression range", k);
    for (uint32_t i = r.begin; i < r.end; ++i)
      if (p.code[i].op == Op::Const &&
          (p.code[i].arg < 0 || static_cast<size_t>(p.code[i].arg) >= p.consts.size()))
        violated("constant index", k);
  };
  if (!p.loopParents.empty() && p.loopParents.size() != nb) violated("loop parents size", 0);
  for (size_t k = 0; k < nb; ++k) {
    const Block& b = p.blocks[k];
    if (b.ops >= 0 && static_cast<size_t>(b.ops) >= p.macroOps.size())
      violated("macro operands", k);
    const MacroOps& o = p.ops(b);
    if (static_cast<size_t>(b.firstWord) + b.nWords > p.words.size()) violated("word range", k);
    for (uint32_t w = 0; w < b.nWords; ++w) {
      const Word& wd = p.words[b.firstWord + w];
      if (wd.kind == WordKind::Expr) expr(wd.a, k);
    }
    expr(o.cond, k);
    expr(o.lhsExpr, k);
    expr(o.rhs, k);
    expr(o.gotoExpr, k);
    if (b.comment >= 0 && static_cast<size_t>(b.comment) >= p.strings.size())
      violated("comment", k);
    if (static_cast<size_t>(o.firstPrint) + o.nPrint > p.prints.size()) violated("print range", k);
    for (uint32_t i = 0; i < o.nPrint; ++i) {
      const PrintItem& it = p.prints[o.firstPrint + i];
      if (it.isVar) expr(it.expr, k);
    }
    if (b.kind == BlockKind::Error &&
        (o.error < 0 || static_cast<size_t>(o.error) >= p.errors.size()))
      violated("error index", k);
    if (b.kind == BlockKind::Assign && o.lhsVar < 0 && o.lhsExpr < 0)
      violated("assignment target", k);
    const int32_t parent = p.loopParent(k);
    if (parent >= 0 && (static_cast<size_t>(parent) >= nb ||
                        p.blocks[static_cast<size_t>(parent)].kind != BlockKind::While))
      violated("loop parent", k);
    // Jump targets are only guaranteed when the program has no structural error (the
    // control refuses to run it otherwise).
    if (p.structural.empty()) {
      if (b.kind == BlockKind::While && (o.target < 0 || static_cast<size_t>(o.target) > nb))
        violated("WHILE target", k);
      if (b.kind == BlockKind::End &&
          (o.target < 0 || static_cast<size_t>(o.target) >= nb ||
           p.blocks[static_cast<size_t>(o.target)].kind != BlockKind::While))
        violated("END target", k);
      bool literalJump =
          (b.kind == BlockKind::Goto || (b.kind == BlockKind::If && !o.thenAssign)) &&
          o.gotoExpr < 0 && o.gotoLabel >= 0;
      if (literalJump && (o.target < 0 || static_cast<size_t>(o.target) >= nb))
        violated("GOTO target", k);
    }
  }
  for (const auto& [n, index] : p.labels)
    if (index >= nb) violated("label index", index);
}

}  // namespace ncvm::fuzz
