// Where the original reports errors whose position is not simply the node's own location. The
// original compiles every expression to postfix code in which each instruction carries a source
// position (int_parse_N.c HF_GEN_CODE) and evaluates it backwards from the last instruction;
// some errors are reported at whatever instruction the evaluator stopped on. These functions
// reconstruct those instructions from the AST.
#pragma once

#include "Language/ast.h"
#include "Language/source_location.h"

namespace frep::semantics
{

/// Position of the FIRST instruction of an expression's postfix code: its leftmost innermost
/// operand (`k+1` -> k; `x[1]` -> 1, since the index code precedes the element instruction;
/// `f(c, 2)` -> c). "Array index out of range" on a read is reported there (int_calc.c 509).
SourceLocation first_instruction_location(const ast::Expr& expr);

/// Position of the first SOURCE token of an expression as far as the AST keeps it (parentheses
/// are not kept, so `(k)` gives k's position). "Array index out of range" on a write is reported
/// at the first token of the index expression (the instruction reserved when parsing of the
/// index starts, int_parse_N.c 1863-1881 and 1925-1946).
SourceLocation first_token_location(const ast::Expr& expr);

/// The write position: the parser's AssignElement::index_end when it lies before the
/// AST-derived first token (an opening parenthesis the AST dropped), else first_token_location.
SourceLocation index_write_location(const ast::Expr& index, SourceLocation index_first_token);

/// Where an object call reports "Some items of array are unassigned": for the x argument the
/// original uses the instruction of the a argument, for the a and s arguments the instruction of
/// the s argument, which is the closing parenthesis when s is omitted (int_calc.c 310-331,
/// int_parse_N.c 916-935).
SourceLocation object_call_x_check_location(const ast::ObjectCallExpr& call);
SourceLocation object_call_as_check_location(const ast::ObjectCallExpr& call,
  SourceLocation call_location);

} // namespace frep::semantics
