// Lowering: symbolic execution of one object's AST into a Dag, at specialisation time. The
// parameters a[] and the fixed coordinates are constants, the free coordinates are Input nodes,
// so everything that depends only on constants folds away (slices of n-D models give small
// tapes, loops over constants unroll). Run-time checks of the original become ordered guards.
#pragma once

#include "Compiler/detail/dag.h"
#include "Compiler/model.h"
#include "Compiler/tape.h"
#include "Language/ast.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace frep::compiler
{

/// The object cannot be turned into a DAG (e.g. a loop whose condition depends on x); the
/// caller falls back to the interpreter.
struct CannotCompile : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Something with an effect, in evaluation order: a guard (error `error_id` when `node`, a
/// boolean, is true) or an opaque call (`node` is the Call node).
struct Effect
{
  bool is_call = false;
  NodeId node = 0;
  int error_id = 0; ///< 1-based, guards only
};

struct Lowered
{
  explicit Lowered(std::size_t max_nodes)
    : dag(max_nodes)
  {
  }
  Dag dag;
  std::vector<Effect> effects;
  std::vector<TapeError> errors;
  std::vector<NodeId> outputs; ///< value, s[1..s_dim]
  std::uint32_t input_count = 0;
};

/// Lowers program.objects[object_index] for `specialisation` (sizes already validated).
/// Throws CannotCompile or DagTooLarge.
void lower(const ast::Program& program,
  int object_index,
  const Specialisation& specialisation,
  const CompileOptions& options,
  Lowered& out);

/// The tape input index of every coordinate (-1 = fixed), from a validated specialisation.
std::vector<int> input_indices(int x_dim, const Specialisation& specialisation);

} // namespace frep::compiler
