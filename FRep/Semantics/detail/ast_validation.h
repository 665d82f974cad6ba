// Structural checks of a resolved AST before it is evaluated: every slot, arity, argument kind,
// call target and array size must be what the parser guarantees. The interpreter validates once
// at construction so that evaluating a point never needs a bounds check on the AST itself (and a
// hand-built or corrupted AST is rejected with an exception instead of crashing).
#pragma once

#include "Language/ast.h"

namespace frep::semantics
{

/// Number of items of a whole-array reference inside `object` (-1 when the reference is invalid).
int array_size(const ast::Object& object, const ast::ArrayName& array);

/// Checks program.objects[object_index] and every object it calls, directly or not.
/// Throws std::invalid_argument describing the first problem.
void validate_object_graph(const ast::Program& program, int object_index);

} // namespace frep::semantics
