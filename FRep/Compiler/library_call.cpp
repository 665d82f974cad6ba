#include "Compiler/detail/library_call.h"

#include "Semantics/detail/error_positions.h"
#include "Semantics/interpreter.h"
#include "Semantics/detail/runtime_messages.h"
#include "Library/library.h"

#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace frep::compiler
{

namespace
{

// The two texts hfConvLine / hfConvCurve pass to error() in the library implementation.
constexpr const char* kAbortMessages[] = {
  "ERROR:Tips of the segment take same coordinate!",
  "Tips of the segment take same coordinate!",
};

class LibraryFunction final : public OpaqueFunction
{
public:
  struct Scratch final : OpaqueFunction::Scratch
  {
    std::vector<double> items;
    std::vector<library::Arg<double>> args;
  };

  LibraryFunction(FunctionId id,
    std::vector<std::size_t> buffer_of,
    std::vector<bool> is_array,
    std::vector<std::size_t> sizes,
    std::vector<std::pair<std::string, int>> aborts)
    : id_(id)
    , buffer_of_(std::move(buffer_of))
    , is_array_(std::move(is_array))
    , sizes_(std::move(sizes))
    , aborts_(std::move(aborts))
  {
    std::size_t offset = 0;
    for (std::size_t s : sizes_)
    {
      offsets_.push_back(offset);
      offset += s;
    }
    item_count_ = offset;
  }

  std::unique_ptr<OpaqueFunction::Scratch> make_scratch() const override
  {
    auto s = std::make_unique<Scratch>();
    s->items.resize(item_count_);
    s->args.resize(is_array_.size());
    return s;
  }

  int evaluate(OpaqueFunction::Scratch* scratch,
    std::span<const double> inputs,
    std::span<double> outputs) const override
  {
    const std::size_t n = is_array_.size();
    if (inputs.size() != 1 + n + item_count_ || outputs.size() != 1 + item_count_)
    {
      return aborts_.empty() ? 0 : aborts_.front().second;
    }
    const std::span<const double> items_in = inputs.subspan(1 + n);
    if (inputs[0] == 0.0)
    {
      outputs[0] = 0.0;
      std::copy(items_in.begin(), items_in.end(), outputs.begin() + 1);
      return 0;
    }
    Scratch local;
    auto* s = scratch ? static_cast<Scratch*>(scratch) : &local;
    s->items.assign(items_in.begin(), items_in.end());
    s->args.assign(n, library::Arg<double>{});
    for (std::size_t i = 0; i < n; ++i)
    {
      s->args[i].real = inputs[1 + i];
      if (is_array_[i])
      {
        const std::size_t b = buffer_of_[i];
        s->args[i].array = std::span<double>(s->items.data() + offsets_[b], sizes_[b]);
      }
    }
    library::DoubleContext context;
    const double value = library::call(id_, std::span(s->args), context);
    if (context.abort_message)
    {
      for (const auto& [message, error] : aborts_)
      {
        if (*context.abort_message == message)
        {
          return error;
        }
      }
      return aborts_.empty() ? 0 : aborts_.front().second;
    }
    outputs[0] = value;
    std::copy(s->items.begin(), s->items.end(), outputs.begin() + 1);
    return 0;
  }

private:
  FunctionId id_;
  std::vector<std::size_t> buffer_of_;
  std::vector<bool> is_array_;
  std::vector<std::size_t> sizes_;
  std::vector<std::size_t> offsets_;
  std::size_t item_count_ = 0;
  std::vector<std::pair<std::string, int>> aborts_;
};

class InterpreterFunction final : public OpaqueFunction
{
public:
  struct Scratch final : OpaqueFunction::Scratch
  {
    explicit Scratch(std::shared_ptr<const ast::Program> program, int object)
      : interpreter(std::move(program), object)
    {
    }
    Interpreter interpreter;
  };

  InterpreterFunction(std::shared_ptr<const ast::Program> program,
    int object,
    std::vector<double> parameters,
    const std::vector<TapeError>& errors,
    int unknown_error)
    : program_(std::move(program))
    , object_(object)
    , parameters_(std::move(parameters))
    , unknown_error_(unknown_error)
  {
    for (std::size_t i = 0; i < errors.size(); ++i)
    {
      ids_.emplace(std::make_tuple(errors[i].message, errors[i].location.line,
                     errors[i].location.column, errors[i].file),
        static_cast<int>(i + 1));
    }
  }

  std::unique_ptr<OpaqueFunction::Scratch> make_scratch() const override
  {
    return std::make_unique<Scratch>(program_, object_);
  }

  int evaluate(OpaqueFunction::Scratch* scratch,
    std::span<const double> inputs,
    std::span<double> outputs) const override
  {
    std::unique_ptr<OpaqueFunction::Scratch> local;
    if (!scratch)
    {
      local = make_scratch();
      scratch = local.get();
    }
    Interpreter& interpreter = static_cast<Scratch*>(scratch)->interpreter;
    if (inputs.size() != static_cast<std::size_t>(interpreter.object().x_dim))
    {
      return unknown_error_;
    }
    // Fresh state per point: the compiled path's semantics (see model.h).
    interpreter.set_parameters(parameters_);
    interpreter.reset_attributes();
    const PointResult r = interpreter.evaluate(inputs);
    if (r.error)
    {
      const auto key = std::make_tuple(
        r.error->message, r.error->location.line, r.error->location.column, r.error->file);
      const auto it = ids_.find(key);
      return it != ids_.end() ? it->second : unknown_error_;
    }
    if (!outputs.empty())
    {
      outputs[0] = r.value;
    }
    const std::span<const double> s = interpreter.attributes();
    for (std::size_t k = 0; k + 1 < outputs.size(); ++k)
    {
      outputs[k + 1] = k < s.size() ? s[k] : 0.0;
    }
    return 0;
  }

private:
  std::shared_ptr<const ast::Program> program_;
  int object_;
  std::vector<double> parameters_;
  int unknown_error_;
  // (message, line, column, file) -> the tape's error id
  std::map<std::tuple<std::string, int, int, std::string>, int> ids_;
};

/// Collects the errors each AST construct can raise (see int_calc.c and error_positions.h).
class ErrorCollector
{
public:
  explicit ErrorCollector(const ast::Program& program)
    : program_(program)
  {
  }

  void object(int index)
  {
    if (index < 0 || static_cast<std::size_t>(index) >= program_.objects.size() ||
        !visited_.insert(index).second)
    {
      return;
    }
    const ast::Object& o = program_.objects[static_cast<std::size_t>(index)];
    // Errors inside the object name its file (a HyperFun library file's objects have their own).
    const std::string* caller_file = std::exchange(file_, o.file.empty() ? &program_.file : &o.file);
    block(o.body);
    if (o.result)
    {
      expr(*o.result);
    }
    file_ = caller_file;
  }

  std::vector<TapeError> result;

private:
  void add(const char* message, SourceLocation at)
  {
    if (seen_.insert(std::make_tuple(std::string(message), at.line, at.column, *file_)).second)
    {
      result.push_back(TapeError{ message, at, *file_ });
    }
  }

  void block(const ast::Block& b)
  {
    for (const ast::Stmt& s : b)
    {
      if (const auto* a = std::get_if<ast::AssignScalar>(&s.node))
      {
        expr(*a->value);
      }
      else if (const auto* e = std::get_if<ast::AssignElement>(&s.node))
      {
        expr(*e->index);
        add(messages::kIndexOutOfRange, semantics::index_write_location(*e->index, e->index_end));
        expr(*e->value);
      }
      else if (const auto* i = std::get_if<ast::IfStmt>(&s.node))
      {
        expr(*i->condition);
        block(i->then_block);
        block(i->else_block);
      }
      else if (const auto* w = std::get_if<ast::WhileStmt>(&s.node))
      {
        expr(*w->condition);
        block(w->body);
      }
    }
  }

  void expr(const ast::Expr& e)
  {
    std::visit([&](const auto& n) { node(e, n); }, e.node);
  }

  void node(const ast::Expr&, const ast::NumberExpr&) {}
  void node(const ast::Expr& e, const ast::ScalarExpr&)
  {
    add(messages::kNotInitialized, e.location);
  }
  void node(const ast::Expr& e, const ast::ElementExpr& n)
  {
    if (n.index)
    {
      expr(*n.index);
      add(messages::kIndexOutOfRange, semantics::first_instruction_location(*n.index));
    }
    add(messages::kUnassignedElement, e.location);
  }
  void node(const ast::Expr&, const ast::UnaryExpr& n) { expr(*n.operand); }
  void node(const ast::Expr& e, const ast::BinaryExpr& n)
  {
    expr(*n.rhs);
    expr(*n.lhs);
    if (n.op == ast::BinaryOp::Div)
    {
      add(messages::kDivisionByZero, e.location);
    }
    if (n.op == ast::BinaryOp::Pow)
    {
      add(messages::kZeroPowerBase, e.location);
      add(messages::kNegativePowerBase, e.location);
    }
  }
  void node(const ast::Expr&, const ast::CompareExpr& n)
  {
    expr(*n.rhs);
    expr(*n.lhs);
  }
  void node(const ast::Expr&, const ast::LogicExpr& n)
  {
    expr(*n.rhs);
    expr(*n.lhs);
  }
  void node(const ast::Expr&, const ast::NotExpr& n) { expr(*n.operand); }
  void node(const ast::Expr& e, const ast::CallExpr& n)
  {
    for (const ast::CallArg& a : n.args)
    {
      if (const auto* p = std::get_if<ast::ExprPtr>(&a); p && *p)
      {
        expr(**p);
      }
      else if (const auto* arr = std::get_if<ast::ArrayName>(&a))
      {
        add(messages::kUnassignedArray, arr->location);
      }
    }
    switch (n.function)
    {
      case FunctionId::Sqrt:
        add(messages::kNegativeSqrt, e.location);
        break;
      case FunctionId::Log:
      case FunctionId::Logd:
        add(messages::kNegativeLog, e.location);
        break;
      case FunctionId::Tan:
        add(messages::kTanArgument, e.location);
        break;
      case FunctionId::Asin:
      case FunctionId::Acos:
        add(messages::kAsinAcosRange, e.location);
        break;
      default:
        if (n.function >= FunctionId::Sphere)
        {
          for (const char* m : kAbortMessages)
          {
            add(m, e.location);
          }
        }
        break;
    }
  }
  void node(const ast::Expr& e, const ast::UserCallExpr& n)
  {
    for (const ast::CallArg& a : n.args)
    {
      if (const auto* p = std::get_if<ast::ExprPtr>(&a); p && *p)
      {
        expr(**p);
      }
      else if (const auto* arr = std::get_if<ast::ArrayName>(&a))
      {
        add(messages::kUnassignedArray, arr->location);
      }
    }
    if (program_.user_functions && n.function >= 0 && n.function < program_.user_functions->size())
    {
      add(user_function_error(program_.user_functions->at(n.function).name).c_str(), e.location);
    }
  }
  void node(const ast::Expr& e, const ast::ObjectCallExpr& n)
  {
    add(messages::kUnassignedArray, semantics::object_call_x_check_location(n));
    add(messages::kUnassignedArray, semantics::object_call_as_check_location(n, e.location));
    object(n.object);
  }

  const ast::Program& program_;
  const std::string* file_ = &program_.file;
  std::set<int> visited_;
  std::set<std::tuple<std::string, int, int, std::string>> seen_;
};

} // namespace

std::span<const char* const> library_abort_messages()
{
  return kAbortMessages;
}

std::shared_ptr<const OpaqueFunction> make_library_function(FunctionId id,
  std::vector<std::size_t> buffer_of,
  std::vector<bool> is_array,
  std::vector<std::size_t> buffer_sizes,
  std::vector<std::pair<std::string, int>> aborts)
{
  return std::make_shared<LibraryFunction>(
    id, std::move(buffer_of), std::move(is_array), std::move(buffer_sizes), std::move(aborts));
}

std::shared_ptr<const OpaqueFunction> make_interpreter_function(
  std::shared_ptr<const ast::Program> program,
  int object_index,
  std::vector<double> parameters,
  std::vector<TapeError> errors,
  int unknown_error)
{
  return std::make_shared<InterpreterFunction>(
    std::move(program), object_index, std::move(parameters), errors, unknown_error);
}

std::vector<TapeError> possible_errors(const ast::Program& program, int object_index)
{
  ErrorCollector collector(program);
  collector.object(object_index);
  return std::move(collector.result);
}

} // namespace frep::compiler
