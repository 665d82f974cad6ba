// An operand of a composed model (combine.h) as part of the composed tape: what the set
// operations, the blends, the product and compose() share.
#pragma once

#include "Compiler/combine.h"
#include "Compiler/detail/lower.h"

#include <vector>

namespace frep::compiler
{

/// The free coordinates of a valid specialisation, in tape input order (0-based).
std::vector<int> free_coordinates(int x_dim, const Specialisation& s);

/// Specialises `operand` for the composed model's specialisation `spec` (its free coordinate i
/// is the composed model's coordinate first + i: fixed there, it is fixed in the operand too;
/// `input_of` maps the composed coordinates to tape inputs, input_indices) and appends its tape
/// to `lowered`; returns the nodes of its outputs (value, s[1..]).
std::vector<NodeId> append_operand(const Operand& operand,
  const std::vector<int>& free,
  int first,
  const Specialisation& spec,
  const std::vector<int>& input_of,
  Lowered& lowered);

} // namespace frep::compiler
