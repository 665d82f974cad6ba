// Composed models: a set operation, blend or Cartesian product of two models, each taken with
// its own specialisation (fixed coordinates, a[], order of the free coordinates). The result is
// a Model like any other: it can be specialised again (a slice of a union), evaluated by every
// evaluator, and combined further.
//
// Coordinates: the result's coordinates are the operands' FREE coordinates, in each operand's
// free-coordinate order (its input_order, or increasing). Set operations and blends need both
// operands to have the same number k of free coordinates; result coordinate i feeds free
// coordinate i of both. The Cartesian product has kA + kB coordinates, A's then B's.
//
// Values, bit for bit as the language computes them (Opcode::Union / Intersect):
//   Union a | b, Intersection a & b, Difference a \ b = Intersect(a, -b),
//   BlendUnion hfBlendUni(a, b, a0, a1, a2), BlendIntersection hfBlendInt(a, b, a0, a1, a2)
//   (the library's own generic formula), CartesianProduct A(xA) & B(xB) (the language's `@`).
// The operands are evaluated right first, as the original evaluates `A | B` (and the arguments
// of a library call, last first): a point where both fail reports B's error.
//
// s[]: s_dim = max(sA, sB); where F_A >= F_B the result's s[] is A's (0 beyond A's s_dim), else
// B's (also where F_A or F_B is NaN), so the colours of a union follow the operand that is
// visible there. a[]: none (a_dim 0): the operands' parameters are in their specialisations.
#pragma once

#include "Compiler/model.h"

#include <memory>
#include <string>

namespace frep
{

enum class Operation
{
  Union,
  Intersection,
  Difference,
  BlendUnion,
  BlendIntersection,
  CartesianProduct
};

/// Lower-case name, as it appears in the name of a composed model: "union", "intersection",
/// "difference", "blend_union", "blend_intersection", "product".
const char* operation_name(Operation operation);

/// One operand: a model and how it is specialised (its free coordinates become the result's).
struct Operand
{
  std::shared_ptr<const Model> model;
  Specialisation specialisation;
};

/// Parameters of the blends (ignored by the other operations): hfBlendUni/hfBlendInt's
/// displacement a0 and its fall-off a1 (along F_A) and a2 (along F_B). a1 = 0 or a2 = 0 gives
/// IEEE inf/NaN, as in the library.
struct OperationParameters
{
  double a0 = 1;
  double a1 = 1;
  double a2 = 1;
};

struct CombineResult
{
  std::shared_ptr<const Model> model; ///< null on error
  std::string error;                  ///< why there is no model (empty on success)
  bool ok() const { return model != nullptr; }
};

/// Makes the model `a op b`, named e.g. "union(ball, box)". Errors come back as values: a null
/// operand model, a specialisation that does not fit its model, or (set operations and blends)
/// operands with different numbers of free coordinates.
CombineResult combine(Operation operation,
  Operand a,
  Operand b,
  const OperationParameters& parameters = {});

/// One coordinate of the outer model of a composition: one of the composed model's own
/// coordinates (`coordinate`, 0-based, when `function.model` is null), or a model of them
/// (`function`: its free coordinates, by its specialisation, are the composed model's, all of
/// them in order).
struct CoordinateFunction
{
  int coordinate = -1;
  Operand function;
};

/// The model G(y) = F(g_1(y), ..., g_n(y)) of `x_dim` coordinates y, named "compose(F)": F is
/// `outer` (its free coordinates, by its specialisation, are fed by `coordinates` in order), each
/// g_i is a coordinate of y or a model of y (a space map, a path through some of F's
/// coordinates). One tape: the g_i's tapes and F's joined (fixing a coordinate of G fixes it
/// in every g_i; values are F's on the g_i's values, bit for bit). s[] are F's; a[] none (the
/// operands' are in their specialisations). Errors as values: a null model, a specialisation
/// that does not fit, as many coordinates as F has free ones, a coordinate outside 0..x_dim-1,
/// a g_i with another number of free coordinates than x_dim.
CombineResult compose(Operand outer, std::vector<CoordinateFunction> coordinates, int x_dim);

} // namespace frep
