// Tree-walking evaluation with the original's semantics (int_calc.c). The original compiles to
// postfix code and evaluates it backwards, which is why the right operand of a binary operator
// and the last argument of a call run first; here the same order is written out explicitly.
//
// Storage mirrors the original's stack: per object a frame with x[], a[], s[], the scalars and
// the local arrays. Callees are always EARLIER objects, so an object is never active twice at
// once and one preallocated frame per object suffices: no allocation per point or per call.
// "Assigned in this evaluation" is a generation stamp per slot, so unsetting every local at the
// start of an evaluation costs one increment.
#include "Semantics/interpreter.h"

#include "Semantics/detail/op_semantics.h"
#include "Semantics/detail/ast_validation.h"
#include "Semantics/detail/error_positions.h"
#include "Semantics/detail/runtime_messages.h"
#include "Library/library.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace frep
{
namespace
{

namespace sem = frep::semantics;

struct Frame
{
  const ast::Object* object = nullptr;
  std::vector<double> x;
  std::vector<double> a;
  std::vector<double> s;
  std::vector<double> scalars;
  std::vector<std::uint64_t> scalar_set; ///< == generation when assigned in this evaluation
  std::vector<double> locals;            ///< every local array, concatenated
  std::vector<std::uint64_t> local_set;
  std::vector<int> local_offset;
  std::uint64_t generation = 0;

  void allocate(const ast::Object& o)
  {
    object = &o;
    x.assign(o.x_dim, 0.0);
    a.assign(o.a_dim, 0.0);
    s.assign(o.s_dim, 0.0);
    scalars.assign(o.scalars.size(), 0.0);
    scalar_set.assign(o.scalars.size(), 0);
    local_offset.clear();
    int total = 0;
    for (const ast::LocalArray& array : o.arrays)
    {
      local_offset.push_back(total);
      total += array.size;
    }
    locals.assign(total, 0.0);
    local_set.assign(total, 0);
  }
};

/// Copies as much of `from` as fits into `to`, zero-filling the rest.
void copy_padded(std::span<const double> from, std::span<double> to)
{
  const std::size_t n = std::min(from.size(), to.size());
  std::copy_n(from.begin(), n, to.begin());
  std::fill(to.begin() + static_cast<std::ptrdiff_t>(n), to.end(), 0.0);
}

class Machine
{
public:
  Machine(const ast::Program& program, int object_index, const InterpreterOptions& options)
    : program_(program)
    , options_(options)
  {
    semantics::validate_object_graph(program, object_index);
    // Frames for the object and everything before it (all possible callees).
    frames_.resize(static_cast<std::size_t>(object_index) + 1);
    for (int i = 0; i <= object_index; ++i)
    {
      frames_[i].allocate(program.objects[i]);
    }
    top_ = &frames_[object_index];
  }

  Frame& top() { return *top_; }
  const Frame& top() const { return *top_; }

  PointResult evaluate(std::span<const double> x)
  {
    copy_padded(x, top_->x);
    loop_budget_ = options_.max_loop_iterations > 0 ? options_.max_loop_iterations
                                                    : std::numeric_limits<std::int64_t>::max();
    PointResult result;
    if (!run_object(*top_, result.value))
    {
      if (error_.file.empty())
      {
        error_.file = file_of(*top_->object);
      }
      result.error = std::move(error_);
      error_ = {};
    }
    return result;
  }

private:
  // ---- failure -------------------------------------------------------------------------------

  // The file errors inside `o` name: its own (a library file's), else the program's.
  const std::string& file_of(const ast::Object& o) const
  {
    return o.file.empty() ? program_.file : o.file;
  }

  bool fail(const char* message, SourceLocation location)
  {
    error_.message = message;
    error_.location = location;
    error_.abort = false;
    error_.file.clear(); // named by the frame that returns it (eval_object_call, evaluate)
    return false;
  }

  // ---- arrays --------------------------------------------------------------------------------

  std::span<double> array_span(const ast::ArrayName& array, Frame& f)
  {
    switch (array.kind)
    {
      case ast::ArrayKind::X:
        return f.x;
      case ast::ArrayKind::A:
        return f.a;
      case ast::ArrayKind::S:
        return f.s;
      case ast::ArrayKind::Local:
        break;
    }
    const int offset = f.local_offset[array.local];
    return std::span<double>(f.locals).subspan(offset, f.object->arrays[array.local].size);
  }

  /// x[], a[] and s[] are always fully set; a local array only when every item was assigned in
  /// this evaluation.
  bool array_assigned(const ast::ArrayName& array, const Frame& f) const
  {
    if (array.kind != ast::ArrayKind::Local)
    {
      return true;
    }
    const int offset = f.local_offset[array.local];
    const int size = f.object->arrays[array.local].size;
    for (int i = 0; i < size; ++i)
    {
      if (f.local_set[offset + i] != f.generation)
      {
        return false;
      }
    }
    return true;
  }

  // ---- objects and statements ----------------------------------------------------------------

  /// Runs an object whose x/a/s are already in its frame. Locals start unset.
  bool run_object(Frame& f, double& out)
  {
    ++f.generation;
    if (!exec_block(f.object->body, f))
    {
      return false;
    }
    return eval(*f.object->result, f, out);
  }

  bool exec_block(const ast::Block& block, Frame& f)
  {
    for (const ast::Stmt& stmt : block)
    {
      if (!exec(stmt, f))
      {
        return false;
      }
    }
    return true;
  }

  bool exec(const ast::Stmt& stmt, Frame& f)
  {
    switch (stmt.node.index())
    {
      case 0: // AssignScalar
      {
        const auto& s = *std::get_if<ast::AssignScalar>(&stmt.node);
        double v;
        if (!eval(*s.value, f, v))
        {
          return false;
        }
        f.scalars[s.scalar] = v;
        f.scalar_set[s.scalar] = f.generation;
        return true;
      }
      case 1: // AssignElement: index first (and its range check), then the value
      {
        const auto& s = *std::get_if<ast::AssignElement>(&stmt.node);
        double iv;
        if (!eval(*s.index, f, iv))
        {
          return false;
        }
        const int i = sem::hf_round(iv);
        const std::span<double> target = array_span(s.array, f);
        if (i < 1 || i > static_cast<int>(target.size()))
        {
          return fail(
            messages::kIndexOutOfRange, semantics::index_write_location(*s.index, s.index_end));
        }
        double v;
        if (!eval(*s.value, f, v))
        {
          return false;
        }
        target[i - 1] = v;
        if (s.array.kind == ast::ArrayKind::Local)
        {
          f.local_set[f.local_offset[s.array.local] + i - 1] = f.generation;
        }
        return true;
      }
      case 2: // AssignArray
      {
        const auto& s = *std::get_if<ast::AssignArray>(&stmt.node);
        const std::span<double> target = array_span(s.array, f);
        const std::size_t n = std::min(target.size(), s.values.size());
        std::copy_n(s.values.begin(), n, target.begin());
        if (s.array.kind == ast::ArrayKind::Local)
        {
          const int offset = f.local_offset[s.array.local];
          std::fill_n(f.local_set.begin() + offset, n, f.generation);
        }
        return true;
      }
      case 3: // IfStmt
      {
        const auto& s = *std::get_if<ast::IfStmt>(&stmt.node);
        double c;
        if (!eval(*s.condition, f, c))
        {
          return false;
        }
        return exec_block(sem::truthy(c) ? s.then_block : s.else_block, f);
      }
      case 4: // WhileStmt
      {
        const auto& s = *std::get_if<ast::WhileStmt>(&stmt.node);
        for (;;)
        {
          double c;
          if (!eval(*s.condition, f, c))
          {
            return false;
          }
          if (!sem::truthy(c))
          {
            return true;
          }
          if (--loop_budget_ < 0)
          {
            return fail(kLoopLimitMessage, stmt.location);
          }
          if (!exec_block(s.body, f))
          {
            return false;
          }
        }
      }
    }
    return true;
  }

  // ---- expressions ---------------------------------------------------------------------------

  bool eval(const ast::Expr& e, Frame& f, double& out)
  {
    switch (e.node.index())
    {
      case 0: // NumberExpr
        out = std::get_if<ast::NumberExpr>(&e.node)->value;
        return true;
      case 1: // ScalarExpr
      {
        const int slot = std::get_if<ast::ScalarExpr>(&e.node)->scalar;
        if (f.scalar_set[slot] != f.generation)
        {
          return fail(messages::kNotInitialized, e.location);
        }
        out = f.scalars[slot];
        return true;
      }
      case 2: // ElementExpr
      {
        const auto& n = *std::get_if<ast::ElementExpr>(&e.node);
        double iv;
        if (!eval(*n.index, f, iv))
        {
          return false;
        }
        const int i = sem::hf_round(iv);
        const std::span<double> array = array_span(n.array, f);
        if (i < 1 || i > static_cast<int>(array.size()))
        {
          return fail(messages::kIndexOutOfRange, semantics::first_instruction_location(*n.index));
        }
        if (n.array.kind == ast::ArrayKind::Local &&
            f.local_set[f.local_offset[n.array.local] + i - 1] != f.generation)
        {
          return fail(messages::kUnassignedElement, e.location);
        }
        out = array[i - 1];
        return true;
      }
      case 3: // UnaryExpr
      {
        const auto& n = *std::get_if<ast::UnaryExpr>(&e.node);
        double v;
        if (!eval(*n.operand, f, v))
        {
          return false;
        }
        out = n.op == ast::UnaryOp::Plus ? v : -v;
        return true;
      }
      case 4: // BinaryExpr
        return eval_binary(e, *std::get_if<ast::BinaryExpr>(&e.node), f, out);
      case 5: // CompareExpr
      {
        const auto& n = *std::get_if<ast::CompareExpr>(&e.node);
        double l, r;
        if (!eval(*n.rhs, f, r) || !eval(*n.lhs, f, l))
        {
          return false;
        }
        bool t = false;
        switch (n.op)
        {
          case ast::CompareOp::Eq:
            t = std::fabs(l - r) < sem::kEps;
            break;
          case ast::CompareOp::Ne:
            t = std::fabs(l - r) >= sem::kEps;
            break;
          case ast::CompareOp::Lt:
            t = l < r;
            break;
          case ast::CompareOp::Le:
            t = l <= r;
            break;
          case ast::CompareOp::Gt:
            t = l > r;
            break;
          case ast::CompareOp::Ge:
            t = l >= r;
            break;
        }
        out = t ? 1.0 : 0.0;
        return true;
      }
      case 6: // LogicExpr: no short circuit, both operands run (right first)
      {
        const auto& n = *std::get_if<ast::LogicExpr>(&e.node);
        double l, r;
        if (!eval(*n.rhs, f, r) || !eval(*n.lhs, f, l))
        {
          return false;
        }
        const bool t = n.op == ast::LogicOp::And ? (sem::truthy(l) && sem::truthy(r))
                                                 : (sem::truthy(l) || sem::truthy(r));
        out = t ? 1.0 : 0.0;
        return true;
      }
      case 7: // NotExpr
      {
        double v;
        if (!eval(*std::get_if<ast::NotExpr>(&e.node)->operand, f, v))
        {
          return false;
        }
        out = sem::truthy(v) ? 0.0 : 1.0;
        return true;
      }
      case 8: // CallExpr
      {
        const auto& n = *std::get_if<ast::CallExpr>(&e.node);
        if (function_info(n.function).builtin)
        {
          return eval_builtin(e, n, f, out);
        }
        return eval_library(e, n, f, out);
      }
      case 9: // ObjectCallExpr
        return eval_object_call(e, *std::get_if<ast::ObjectCallExpr>(&e.node), f, out);
      case 10: // UserCallExpr
        return eval_user(e, *std::get_if<ast::UserCallExpr>(&e.node), f, out);
    }
    return true;
  }

  bool eval_binary(const ast::Expr& e, const ast::BinaryExpr& n, Frame& f, double& out)
  {
    double l, r;
    if (!eval(*n.rhs, f, r) || !eval(*n.lhs, f, l))
    {
      return false;
    }
    switch (n.op)
    {
      case ast::BinaryOp::Add:
        out = l + r;
        return true;
      case ast::BinaryOp::Sub:
        out = l - r;
        return true;
      case ast::BinaryOp::Mul:
        out = l * r;
        return true;
      case ast::BinaryOp::Div:
        if (std::fabs(r) < sem::kEps)
        {
          return fail(messages::kDivisionByZero, e.location);
        }
        out = l / r;
        return true;
      case ast::BinaryOp::Pow:
        switch (sem::hf_pow_error(l, r))
        {
          case sem::PowError::ZeroBase:
            return fail(messages::kZeroPowerBase, e.location);
          case sem::PowError::NegativeBase:
            return fail(messages::kNegativePowerBase, e.location);
          case sem::PowError::None:
            break;
        }
        out = sem::hf_pow(l, r);
        return true;
      case ast::BinaryOp::Union:
        out = sem::unite(l, r);
        return true;
      case ast::BinaryOp::Intersect:
      case ast::BinaryOp::Product:
        out = sem::intersect(l, r);
        return true;
      case ast::BinaryOp::Subtract:
        out = sem::intersect(l, -r); // f1 \ f2 = f1 & -f2, exactly as the original negates
        return true;
    }
    return true;
  }

  bool eval_builtin(const ast::Expr& e, const ast::CallExpr& n, Frame& f, double& out)
  {
    // At most two real arguments; the last one runs first.
    std::array<double, 2> v{};
    for (std::size_t i = n.args.size(); i-- > 0;)
    {
      if (!eval(*std::get<ast::ExprPtr>(n.args[i]), f, v[i]))
      {
        return false;
      }
    }
    const double a = v[0];
    const double b = v[1];
    switch (n.function)
    {
      case FunctionId::Sqrt:
        if (a < 0.0)
        {
          return fail(messages::kNegativeSqrt, e.location);
        }
        out = std::sqrt(a);
        return true;
      case FunctionId::Exp:
        out = std::exp(a);
        return true;
      case FunctionId::Log:
        if (!(a > 0.0))
        {
          return fail(messages::kNegativeLog, e.location);
        }
        out = std::log(a);
        return true;
      case FunctionId::Logd:
        if (!(a > 0.0))
        {
          return fail(messages::kNegativeLog, e.location);
        }
        out = std::log10(a);
        return true;
      case FunctionId::Sin:
        out = std::sin(a);
        return true;
      case FunctionId::Cos:
        out = std::cos(a);
        return true;
      case FunctionId::Tan:
        if (std::fabs(std::cos(a)) < sem::kEps)
        {
          return fail(messages::kTanArgument, e.location);
        }
        out = std::tan(a);
        return true;
      case FunctionId::Asin:
        if (std::fabs(a) > 1.0)
        {
          return fail(messages::kAsinAcosRange, e.location);
        }
        out = std::asin(a);
        return true;
      case FunctionId::Acos:
        if (std::fabs(a) > 1.0)
        {
          return fail(messages::kAsinAcosRange, e.location);
        }
        out = std::acos(a);
        return true;
      case FunctionId::Atan:
        out = std::atan(a);
        return true;
      case FunctionId::Abs:
        out = std::fabs(a);
        return true;
      case FunctionId::Sinh:
        out = std::sinh(a);
        return true;
      case FunctionId::Cosh:
        out = std::cosh(a);
        return true;
      case FunctionId::Tanh:
        out = std::tanh(a);
        return true;
      case FunctionId::Sign:
        out = 1.0; // the original overwrites its -1 (int_calc.c 882-886)
        return true;
      case FunctionId::Mod:
        out = sem::hf_mod(a, b);
        return true;
      case FunctionId::Max:
        out = sem::hf_max(a, b);
        return true;
      case FunctionId::Min:
        out = sem::hf_min(a, b);
        return true;
      case FunctionId::Atan2:
        out = std::atan2(a, b);
        return true;
      case FunctionId::Ceil:
        out = std::ceil(a);
        return true;
      case FunctionId::Floor:
        out = std::floor(a);
        return true;
      case FunctionId::Int:
      {
        double whole;
        std::modf(a, &whole);
        out = whole;
        return true;
      }
      case FunctionId::Frac:
      {
        double whole;
        out = std::modf(a, &whole);
        return true;
      }
      default:
        break;
    }
    return true;
  }

  bool eval_library(const ast::Expr& e, const ast::CallExpr& n, Frame& f, double& out)
  {
    std::array<library::Arg<double>, kMaxFunctionArity> args{};
    // Last to first; array arguments are checked when their turn comes and passed by reference,
    // so in-place transformations made by nested calls are seen, as in the original.
    for (std::size_t i = n.args.size(); i-- > 0;)
    {
      const ast::CallArg& arg = n.args[i];
      if (const auto* expr = std::get_if<ast::ExprPtr>(&arg))
      {
        if (!eval(**expr, f, args[i].real))
        {
          return false;
        }
      }
      else if (const auto* array = std::get_if<ast::ArrayName>(&arg))
      {
        if (!array_assigned(*array, f))
        {
          return fail(messages::kUnassignedArray, array->location);
        }
        args[i].array = array_span(*array, f);
      }
      // A string argument carries no number (no registered function takes one).
    }
    library::DoubleContext context;
    out = library::call(n.function, std::span(args.data(), n.args.size()), context);
    if (context.abort_message)
    {
      error_.message = *context.abort_message;
      error_.location = e.location;
      error_.abort = true;
      error_.file.clear();
      return false;
    }
    return true;
  }

  bool eval_user(const ast::Expr& e, const ast::UserCallExpr& n, Frame& f, double& out)
  {
    const UserFunction& function = program_.user_functions->at(n.function);
    std::array<double, kMaxFunctionArity> reals{};
    std::array<UserArgument, kMaxFunctionArity> args{};
    // Last to first, as a library call's arguments.
    for (std::size_t i = n.args.size(); i-- > 0;)
    {
      const ast::CallArg& arg = n.args[i];
      if (const auto* expr = std::get_if<ast::ExprPtr>(&arg))
      {
        if (!eval(**expr, f, reals[i]))
        {
          return false;
        }
        args[i] = UserArgument{ &reals[i], 1 };
      }
      else if (const auto* array = std::get_if<ast::ArrayName>(&arg))
      {
        if (!array_assigned(*array, f))
        {
          return fail(messages::kUnassignedArray, array->location);
        }
        const std::span<double> items = array_span(*array, f);
        args[i] = UserArgument{ items.data(), static_cast<int>(items.size()) };
      }
    }
    bool ok = false;
    try
    {
      ok = function.point(std::span(args.data(), n.args.size()), out);
    }
    catch (...)
    {
      ok = false; // a throwing user function fails at this point, like any run-time error
    }
    if (!ok)
    {
      fail("", e.location);
      error_.message = user_function_error(function.name);
      return false;
    }
    return true;
  }

  bool eval_object_call(const ast::Expr& e, const ast::ObjectCallExpr& n, Frame& f, double& out)
  {
    Frame& callee = frames_[n.object];
    const std::span<double> xs = array_span(n.x, f);
    const std::span<double> as = array_span(n.a, f);
    // Without a third argument the caller's own s[] is passed (int_parse_N.c 854-866).
    const std::span<double> ss =
      n.s ? array_span(*n.s, f) : std::span<double>(f.s).first(callee.s.size());
    if (!array_assigned(n.x, f))
    {
      return fail(messages::kUnassignedArray, semantics::object_call_x_check_location(n));
    }
    if (!array_assigned(n.a, f) || (n.s && !array_assigned(*n.s, f)))
    {
      return fail(messages::kUnassignedArray, semantics::object_call_as_check_location(n, e.location));
    }
    // The callee works on copies: what it does to its x[] and a[] does not leak back...
    std::copy(xs.begin(), xs.end(), callee.x.begin());
    std::copy(as.begin(), as.end(), callee.a.begin());
    std::copy(ss.begin(), ss.end(), callee.s.begin());
    const bool ok = run_object(callee, out);
    if (!ok && error_.file.empty())
    {
      error_.file = file_of(*callee.object); // it happened in the callee (deeper: named there)
    }
    // ...but its s[] is copied back, even when it failed (int_calc.c 358-371).
    std::copy(callee.s.begin(), callee.s.end(), ss.begin());
    return ok;
  }

  const ast::Program& program_;
  InterpreterOptions options_;
  std::vector<Frame> frames_;
  Frame* top_ = nullptr;
  std::int64_t loop_budget_ = 0;
  RuntimeError error_;
};

} // namespace

struct Interpreter::State
{
  State(const ast::Program& program, int object_index, const InterpreterOptions& options)
    : machine(program, object_index, options)
  {
  }
  Machine machine;
};

Interpreter::Interpreter(std::shared_ptr<const ast::Program> program,
  int object_index,
  const InterpreterOptions& options)
  : program_(std::move(program))
  , object_index_(object_index)
{
  if (!program_)
  {
    throw std::invalid_argument("Interpreter: no program");
  }
  if (object_index_ < 0 || object_index_ >= static_cast<int>(program_->objects.size()))
  {
    throw std::invalid_argument("Interpreter: object index out of range");
  }
  state_ = std::make_unique<State>(*program_, object_index_, options);
}

Interpreter::~Interpreter() = default;
Interpreter::Interpreter(Interpreter&&) noexcept = default;
Interpreter& Interpreter::operator=(Interpreter&&) noexcept = default;

const ast::Object& Interpreter::object() const
{
  return program_->objects[object_index_];
}

void Interpreter::set_parameters(std::span<const double> a)
{
  copy_padded(a, state_->machine.top().a);
}

void Interpreter::reset_attributes()
{
  std::vector<double>& s = state_->machine.top().s;
  std::fill(s.begin(), s.end(), 0.0);
}

PointResult Interpreter::evaluate(std::span<const double> x)
{
  return state_->machine.evaluate(x);
}

std::span<const double> Interpreter::parameters() const
{
  return state_->machine.top().a;
}

std::span<const double> Interpreter::attributes() const
{
  return state_->machine.top().s;
}

} // namespace frep
