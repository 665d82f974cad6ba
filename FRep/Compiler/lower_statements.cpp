// The Lowerer's statements: blocks, assignments, if (both paths, merged), while (unrolled).
#include "Compiler/detail/lowerer.h"

#include <algorithm>
#include <utility>

namespace frep::compiler::lowering
{

void Lowerer::execute_block(Frame& frame, const ast::Block& block)
{
  for (const ast::Stmt& stmt : block)
  {
    if (dead_)
    {
      return;
    }
    std::visit([&](const auto& s) { execute_stmt(frame, stmt, s); }, stmt.node);
  }
}

void Lowerer::execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignScalar& s)
{
  const Expr v = eval(frame, *s.value);
  if (s.scalar < 0 || static_cast<std::size_t>(s.scalar) >= frame.scalars.size())
  {
    throw CannotCompile("malformed AST: bad scalar index");
  }
  frame.scalars[static_cast<std::size_t>(s.scalar)] = Cell{ v, Expr(1.0) };
}

void Lowerer::execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignElement& s)
{
  std::vector<Cell>& cells = frame.array(s.array);
  const Expr index = eval(frame, *s.index);
  const Expr r = apply(Opcode::HfRound, index);
  const auto n = static_cast<double>(cells.size());
  const Expr in_range = logical_and(r >= Expr(1.0), r <= Expr(n));
  guard(logical_not(in_range),
    messages::kIndexOutOfRange,
    semantics::index_write_location(*s.index, s.index_end));
  if (dead_)
  {
    return;
  }
  const Expr v = eval(frame, *s.value);
  if (r.is_constant())
  {
    cells[static_cast<std::size_t>(r.constant()) - 1] = Cell{ v, Expr(1.0) };
    return;
  }
  for (std::size_t k = 0; k < cells.size(); ++k)
  {
    const Expr hit = apply(Opcode::Eq, r, Expr(static_cast<double>(k + 1)));
    cells[k].value = select(hit, v, cells[k].value);
    cells[k].assigned = select(hit, Expr(1.0), cells[k].assigned);
  }
}

void Lowerer::execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignArray& s)
{
  std::vector<Cell>& cells = frame.array(s.array);
  for (std::size_t k = 0; k < s.values.size() && k < cells.size(); ++k)
  {
    cells[k] = Cell{ Expr(s.values[k]), Expr(1.0) };
  }
}

void Lowerer::execute_stmt(Frame& frame, const ast::Stmt&, const ast::IfStmt& s)
{
  const Expr c = apply(Opcode::Truthy, eval(frame, *s.condition));
  if (dead_)
  {
    return;
  }
  if (c.is_constant())
  {
    execute_block(frame, c.constant() != 0 ? s.then_block : s.else_block);
    return;
  }
  // Only the scalars the branches assign can differ between them: those are saved, run in
  // each branch and merged, not the whole frame (a .vm tape's thousands of choices over
  // thousands of scalars would otherwise cost the product). Arrays are few: all are kept.
  const std::vector<int>& touched = assigned_scalars(s);
  std::vector<Cell> before = gather(frame.scalars, touched);
  std::vector<std::vector<Cell>> then_arrays = frame.arrays;
  const Expr outer_path = path_;
  path_ = logical_and(outer_path, c);
  execute_block(frame, s.then_block);
  const bool then_dead = dead_;
  dead_ = false;
  std::vector<Cell> then_scalars = gather(frame.scalars, touched);
  std::swap(then_arrays, frame.arrays); // frame: the state before, then_arrays: the then branch's
  scatter(frame.scalars, touched, before);
  path_ = logical_and(outer_path, logical_not(c));
  execute_block(frame, s.else_block);
  const bool else_dead = dead_;
  path_ = outer_path;
  dead_ = then_dead && else_dead;
  if (then_dead || else_dead)
  {
    // Points on a dead branch have failed: only the live branch's state matters (the frame
    // holds the else branch's).
    if (else_dead && !then_dead)
    {
      scatter(frame.scalars, touched, then_scalars);
      frame.arrays = std::move(then_arrays);
    }
    return;
  }
  std::vector<Cell> else_scalars = gather(frame.scalars, touched);
  merge(c, then_scalars, else_scalars);
  scatter(frame.scalars, touched, then_scalars);
  for (std::size_t i = 0; i < frame.arrays.size(); ++i)
  {
    merge(c, then_arrays[i], frame.arrays[i]);
  }
  frame.arrays = std::move(then_arrays);
}

std::vector<Cell> Lowerer::gather(const std::vector<Cell>& cells, const std::vector<int>& which)
{
  std::vector<Cell> out;
  out.reserve(which.size());
  for (const int k : which)
  {
    out.push_back(cells[static_cast<std::size_t>(k)]);
  }
  return out;
}

void Lowerer::scatter(std::vector<Cell>& cells,
  const std::vector<int>& which,
  const std::vector<Cell>& values)
{
  for (std::size_t i = 0; i < which.size(); ++i)
  {
    cells[static_cast<std::size_t>(which[i])] = values[i];
  }
}

const std::vector<int>& Lowerer::assigned_scalars(const ast::IfStmt& s)
{
  auto [it, inserted] = assigned_scalars_.try_emplace(&s);
  if (inserted)
  {
    std::vector<int>& out = it->second;
    collect_assigned(s.then_block, out);
    collect_assigned(s.else_block, out);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    for (const int k : out)
    {
      if (k < 0)
      {
        throw CannotCompile("malformed AST: bad scalar index");
      }
    }
  }
  return it->second;
}

void Lowerer::collect_assigned(const ast::Block& block, std::vector<int>& out)
{
  for (const ast::Stmt& stmt : block)
  {
    if (const auto* a = std::get_if<ast::AssignScalar>(&stmt.node))
    {
      out.push_back(a->scalar);
    }
    else if (const auto* i = std::get_if<ast::IfStmt>(&stmt.node))
    {
      collect_assigned(i->then_block, out);
      collect_assigned(i->else_block, out);
    }
    else if (const auto* w = std::get_if<ast::WhileStmt>(&stmt.node))
    {
      collect_assigned(w->body, out);
    }
  }
}

void Lowerer::merge(const Expr& c,
  std::vector<Cell>& then_cells,
  const std::vector<Cell>& else_cells)
{
  for (std::size_t k = 0; k < then_cells.size(); ++k)
  {
    Cell& t = then_cells[k];
    const Cell& e = else_cells[k];
    const bool t_unset = t.assigned.is_constant() && t.assigned.constant() == 0;
    const bool e_unset = e.assigned.is_constant() && e.assigned.constant() == 0;
    // Reading an unassigned cell fails before its value is used, so its value is free.
    if (e_unset && !t_unset)
    {
      t.assigned = select(c, t.assigned, e.assigned);
      continue;
    }
    if (t_unset && !e_unset)
    {
      t.value = e.value;
      t.assigned = select(c, t.assigned, e.assigned);
      continue;
    }
    t.value = select(c, t.value, e.value);
    t.assigned = select(c, t.assigned, e.assigned);
  }
}

void Lowerer::execute_stmt(Frame& frame, const ast::Stmt&, const ast::WhileStmt& s)
{
  std::size_t iterations = 0;
  while (!dead_)
  {
    const Expr c = eval(frame, *s.condition);
    if (dead_)
    {
      return;
    }
    if (!c.is_constant())
    {
      throw CannotCompile("a while condition depends on the free coordinates");
    }
    if (!semantics::truthy(c.constant()))
    {
      return;
    }
    if (++iterations > options_.max_unrolled_iterations)
    {
      throw CannotCompile("a while loop runs more iterations than the unrolling limit");
    }
    execute_block(frame, s.body);
  }
}

} // namespace frep::compiler::lowering
