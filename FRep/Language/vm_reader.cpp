#include "Language/vm_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

namespace frep
{

namespace
{

struct Token
{
  std::string_view text;
  int column = 0; ///< 1-based
};

std::vector<Token> split_line(std::string_view line)
{
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t')
    {
      ++i;
    }
    if (i > start)
    {
      tokens.push_back({ line.substr(start, i - start), static_cast<int>(start) + 1 });
    }
  }
  return tokens;
}

ast::ExprPtr make(SourceLocation at, auto node)
{
  auto e = std::make_unique<ast::Expr>();
  e->location = at;
  e->node = std::move(node);
  return e;
}

ast::ExprPtr number(SourceLocation at, double value)
{
  return make(at, ast::NumberExpr{ value });
}

ast::ExprPtr scalar(SourceLocation at, int index)
{
  return make(at, ast::ScalarExpr{ index });
}

ast::ExprPtr coordinate(SourceLocation at, int k)
{
  ast::ElementExpr element;
  element.array.kind = ast::ArrayKind::X;
  element.array.location = at;
  element.index = number(at, k + 1);
  element.index_end = at;
  return make(at, std::move(element));
}

ast::ExprPtr binary(SourceLocation at, ast::BinaryOp op, ast::ExprPtr a, ast::ExprPtr b)
{
  return make(at, ast::BinaryExpr{ op, std::move(a), std::move(b) });
}

ast::ExprPtr call(SourceLocation at, FunctionId f, std::vector<ast::ExprPtr> operands)
{
  ast::CallExpr c;
  c.function = f;
  for (auto& e : operands)
  {
    c.args.emplace_back(std::move(e));
  }
  return make(at, std::move(c));
}

ast::ExprPtr compare(SourceLocation at, ast::CompareOp op, ast::ExprPtr l, ast::ExprPtr r)
{
  return make(at, ast::CompareExpr{ op, std::move(l), std::move(r) });
}

ast::Stmt assign(SourceLocation at, int target, ast::ExprPtr value)
{
  ast::Stmt stmt;
  stmt.location = at;
  stmt.node = ast::AssignScalar{ target, std::move(value) };
  return stmt;
}

/// if condition then then_stmt else else_stmt endif; (lowered to a Select: no fallback)
ast::Stmt if_else(SourceLocation at,
  ast::ExprPtr condition,
  ast::Stmt then_stmt,
  ast::Stmt else_stmt)
{
  ast::IfStmt s;
  s.condition = std::move(condition);
  s.then_block.push_back(std::move(then_stmt));
  s.else_block.push_back(std::move(else_stmt));
  ast::Stmt stmt;
  stmt.location = at;
  stmt.node = std::move(s);
  return stmt;
}

/// Operands each opcode takes (-1: unknown opcode, -2: const's number).
int operand_count_of(std::string_view op)
{
  static const std::unordered_map<std::string_view, int> counts = { { "const", -2 },
    { "var-x", 0 },
    { "var-y", 0 },
    { "var-z", 0 },
    { "neg", 1 },
    { "square", 1 },
    { "sqrt", 1 },
    { "abs", 1 },
    { "recip", 1 },
    { "exp", 1 },
    { "ln", 1 },
    { "sin", 1 },
    { "cos", 1 },
    { "tan", 1 },
    { "asin", 1 },
    { "acos", 1 },
    { "atan", 1 },
    { "floor", 1 },
    { "ceil", 1 },
    { "round", 1 },
    { "not", 1 },
    { "add", 2 },
    { "sub", 2 },
    { "mul", 2 },
    { "div", 2 },
    { "min", 2 },
    { "max", 2 },
    { "atan2", 2 },
    { "compare", 2 },
    { "and", 2 },
    { "or", 2 },
    { "mod", 2 } };
  const auto it = counts.find(op);
  return it == counts.end() ? -1 : it->second;
}

constexpr const char* kKnownOpcodes =
  "const var-x var-y var-z neg square sqrt abs recip exp ln sin cos tan asin acos atan floor "
  "ceil round not add sub mul div min max atan2 compare and or mod";

/// Helper scalars by role ("mod~q", ...), shared by all instructions: each instruction assigns
/// its helpers before reading them, and the compiler's cost of an if-statement grows with the
/// number of scalars of the object.
using HelperPool = std::unordered_map<std::string, int>;

/// Writes the statements of one instruction `target = op(operands)` into the object's body.
/// Opcodes with a data-dependent choice become if-statements over exact comparisons (the
/// compiler merges both branches with Select); helper values live in hidden scalars whose names
/// contain '~' and are not in the reader's name table, so no instruction can refer to them.
class Emitter
{
public:
  /// at: the opcode (the position of run-time errors); line_at: the line's first token.
  Emitter(ast::Object& object,
    HelperPool& pool,
    SourceLocation at,
    SourceLocation line_at,
    int target,
    std::vector<int> operands)
    : object_(object)
    , pool_(pool)
    , at_(at)
    , line_at_(line_at)
    , target_(target)
    , operands_(std::move(operands))
  {
  }

  /// The value of operand k (a fresh node each call).
  ast::ExprPtr arg(int k) const { return scalar(at_, operands_.at(static_cast<std::size_t>(k))); }
  ast::ExprPtr get(int s) const { return scalar(at_, s); }
  ast::ExprPtr num(double v) const { return number(at_, v); }
  ast::ExprPtr bin(ast::BinaryOp op, ast::ExprPtr a, ast::ExprPtr b) const
  {
    return binary(at_, op, std::move(a), std::move(b));
  }
  ast::ExprPtr fn(FunctionId f, ast::ExprPtr a) const
  {
    std::vector<ast::ExprPtr> v;
    v.push_back(std::move(a));
    return call(at_, f, std::move(v));
  }
  ast::ExprPtr fn(FunctionId f, ast::ExprPtr a, ast::ExprPtr b) const
  {
    std::vector<ast::ExprPtr> v;
    v.push_back(std::move(a));
    v.push_back(std::move(b));
    return call(at_, f, std::move(v));
  }
  ast::ExprPtr cmp(ast::CompareOp op, ast::ExprPtr a, ast::ExprPtr b) const
  {
    return compare(at_, op, std::move(a), std::move(b));
  }
  /// v == 0 exactly, false for NaN: (v >= 0 and v <= 0). (HyperFun's `=` has a tolerance.)
  ast::ExprPtr is_zero(int s) const
  {
    return make(at_,
      ast::LogicExpr{ ast::LogicOp::And,
        cmp(ast::CompareOp::Ge, get(s), num(0.0)),
        cmp(ast::CompareOp::Le, get(s), num(0.0)) });
  }

  ast::Stmt set(int s, ast::ExprPtr value) const { return assign(at_, s, std::move(value)); }
  void emit(ast::Stmt stmt) { object_.body.push_back(std::move(stmt)); }
  /// target = value
  void result(ast::ExprPtr value) { emit(assign(line_at_, target_, std::move(value))); }
  /// The helper scalar of a role (assign it before use).
  int fresh(std::string_view role)
  {
    const auto [it, added] =
      pool_.try_emplace(std::string(role), static_cast<int>(object_.scalars.size()));
    if (added)
    {
      object_.scalars.push_back(it->first);
    }
    return it->second;
  }
  /// A new hidden scalar assigned `value` now.
  int temp(std::string_view what, ast::ExprPtr value)
  {
    const int s = fresh(what);
    emit(set(s, std::move(value)));
    return s;
  }
  ast::ExprPtr neg(ast::ExprPtr a) const
  {
    return make(at_, ast::UnaryExpr{ ast::UnaryOp::Minus, std::move(a) });
  }
  SourceLocation at() const { return at_; }
  int target() const { return target_; }
  int operand(int k) const { return operands_.at(static_cast<std::size_t>(k)); }

private:
  ast::Object& object_;
  HelperPool& pool_;
  SourceLocation at_;
  SourceLocation line_at_;
  int target_;
  std::vector<int> operands_;
};

/// round a: half away from zero (C round, Rust's f32::round), exactly and without a branch:
/// int(a) + int(2 * frac(a)). frac(a) = a - int(a) is exact and 2 * frac(a) too, so the second
/// term is 1 for frac >= 0.5, -1 for frac <= -0.5, else a zero of a's sign: round(-0.3) = -0,
/// round(0.49999999999999994) = 0, infinities (frac = 0) and NaN stay.
void emit_round(Emitter& e)
{
  using ast::BinaryOp;
  e.result(e.bin(BinaryOp::Add,
    e.fn(FunctionId::Int, e.arg(0)),
    e.fn(FunctionId::Int, e.bin(BinaryOp::Mul, e.num(2.0), e.fn(FunctionId::Frac, e.arg(0))))));
}

/// sign(v) as -1, 0 or 1 for a v that is 0 or at least 2^-1074 in magnitude (every double):
/// min(1, max(-1, v * 2^1000 * 2^74)); NaN stays NaN (HyperFun's max/min: a > b ? a : b).
ast::ExprPtr clamped_sign(const Emitter& e, ast::ExprPtr v)
{
  using ast::BinaryOp;
  ast::ExprPtr big = e.bin(BinaryOp::Mul,
    e.bin(BinaryOp::Mul, std::move(v), e.num(std::ldexp(1.0, 1000))),
    e.num(std::ldexp(1.0, 74)));
  return e.fn(FunctionId::Min, e.num(1.0), e.fn(FunctionId::Max, e.num(-1.0), std::move(big)));
}

/// compare a b: 0 if a == b (infinities too), else the sign of a - b (nonzero for a != b: no
/// underflow to zero; +-inf when it overflows), NaN if either is NaN.
void emit_compare(Emitter& e)
{
  const int d = e.temp("compare~d", e.bin(ast::BinaryOp::Sub, e.arg(0), e.arg(1)));
  e.emit(if_else(e.at(),
    make(e.at(),
      ast::LogicExpr{ ast::LogicOp::And,
        e.cmp(ast::CompareOp::Ge, e.arg(0), e.arg(1)),
        e.cmp(ast::CompareOp::Le, e.arg(0), e.arg(1)) }),
    e.set(e.target(), e.num(0.0)),
    e.set(e.target(), clamped_sign(e, e.get(d)))));
}

/// Dekker's exact residual v - n * m (no FMA): the product split into p + err exactly
/// (Veltkamp halves n = nh + nl, m = mh + ml), then (v - p) - err. Exact when v - n * m is a
/// double and v - p is exact (Sterbenz: p within a factor 2 of v), without overflow
/// (|n|, |m| < 2^996) or underflow.
int emit_residual(Emitter& e, std::string_view tag, int v, int n, int m, int mh, int ml)
{
  using ast::BinaryOp;
  const std::string t(tag);
  const auto mul = [&](int a, int b) { return e.bin(BinaryOp::Mul, e.get(a), e.get(b)); };
  const int nc = e.temp(t + "c", e.bin(BinaryOp::Mul, e.num(134217729.0), e.get(n)));
  const int nh =
    e.temp(t + "h", e.bin(BinaryOp::Sub, e.get(nc), e.bin(BinaryOp::Sub, e.get(nc), e.get(n))));
  const int nl = e.temp(t + "l", e.bin(BinaryOp::Sub, e.get(n), e.get(nh)));
  const int p = e.temp(t + "p", mul(n, m));
  // err = (((nh*mh - p) + nh*ml) + nl*mh) + nl*ml
  ast::ExprPtr err = e.bin(BinaryOp::Sub, mul(nh, mh), e.get(p));
  err = e.bin(BinaryOp::Add, std::move(err), mul(nh, ml));
  err = e.bin(BinaryOp::Add, std::move(err), mul(nl, mh));
  err = e.bin(BinaryOp::Add, std::move(err), mul(nl, ml));
  const int r = e.temp(t + "e", std::move(err));
  return e.temp(t, e.bin(BinaryOp::Sub, e.bin(BinaryOp::Sub, e.get(v), e.get(p)), e.get(r)));
}

/// mod a b: Rust's rem_euclid (Fidget's `mod`) in doubles: f = fmod(a, b), f < 0 ? f + |b| : f.
/// The AST has no plain fmod (HyperFun's mod rounds its operands), so it is computed exactly,
/// for |a / b| < 2^52: v = |a|, m = |b|, q = v / m (HyperFun's division: |b| < 1e-6 is
/// "Division by zero"), n = int(q), which is N = trunc(v / m) or, when q rounded up to an
/// integer, N + 1. The exact residual t = v - n * m' with m' = min(m, v) (= m unless v < m,
/// where n = 0 and t = v, also for m = inf) is r = fmod(v, m), or r - m, a double then
/// (Sterbenz: r >= m / 2). s = t with the sign of a, of a zero too (fmod(-0, b) = -0): times
/// min(1, max(-1, atan2(a, -1))), which is -1 exactly when a's sign bit is set. The final fix
/// s < 0 ? s + m : s gives rem_euclid in both cases, exactly: for a > 0, (r - m) + m = r; for
/// a < 0, -(r - m) = m - r, which is what -r + m rounds to (it is a double).
void emit_mod(Emitter& e)
{
  using ast::BinaryOp;
  using ast::CompareOp;
  const int v = e.temp("mod~v", e.fn(FunctionId::Abs, e.arg(0)));
  const int m = e.temp("mod~m", e.fn(FunctionId::Abs, e.arg(1)));
  const int q = e.temp("mod~q", e.bin(BinaryOp::Div, e.get(v), e.get(m)));
  const int n = e.temp("mod~n", e.fn(FunctionId::Int, e.get(q)));
  const int mm = e.temp("mod~m'", e.fn(FunctionId::Min, e.get(m), e.get(v)));
  const int mc = e.temp("mod~mc", e.bin(BinaryOp::Mul, e.num(134217729.0), e.get(mm)));
  const int mh =
    e.temp("mod~mh", e.bin(BinaryOp::Sub, e.get(mc), e.bin(BinaryOp::Sub, e.get(mc), e.get(mm))));
  const int ml = e.temp("mod~ml", e.bin(BinaryOp::Sub, e.get(mm), e.get(mh)));
  const int t = emit_residual(e, "mod~t", v, n, mm, mh, ml);
  const int s = e.temp("mod~s",
    e.bin(BinaryOp::Mul,
      e.get(t),
      e.fn(FunctionId::Min,
        e.num(1.0),
        e.fn(FunctionId::Max, e.num(-1.0), e.fn(FunctionId::Atan2, e.arg(0), e.num(-1.0))))));
  e.emit(if_else(e.at(),
    e.cmp(CompareOp::Lt, e.get(s), e.num(0.0)),
    e.set(e.target(), e.bin(BinaryOp::Add, e.get(s), e.get(m))),
    e.set(e.target(), e.get(s))));
}

/// and/or/not: exact zero tests (Fidget: and a b = a == 0 ? a : b; or a b = a != 0 ? a : b;
/// not a = a == 0 ? 1 : 0; NaN is not zero).
void emit_logic(Emitter& e, std::string_view op)
{
  const int a = e.operand(0);
  if (op == "and")
  {
    e.emit(if_else(e.at(), e.is_zero(a), e.set(e.target(), e.arg(0)), e.set(e.target(), e.arg(1))));
  }
  else if (op == "or")
  {
    e.emit(if_else(e.at(), e.is_zero(a), e.set(e.target(), e.arg(1)), e.set(e.target(), e.arg(0))));
  }
  else
  {
    e.emit(
      if_else(e.at(), e.is_zero(a), e.set(e.target(), e.num(1.0)), e.set(e.target(), e.num(0.0))));
  }
}

/// The one-call opcodes: the HyperFun builtin of the same meaning.
std::optional<FunctionId> builtin_of(std::string_view op)
{
  static const std::unordered_map<std::string_view, FunctionId> builtins = { { "sqrt",
                                                                               FunctionId::Sqrt },
    { "abs", FunctionId::Abs },
    { "exp", FunctionId::Exp },
    { "ln", FunctionId::Log },
    { "sin", FunctionId::Sin },
    { "cos", FunctionId::Cos },
    { "tan", FunctionId::Tan },
    { "asin", FunctionId::Asin },
    { "acos", FunctionId::Acos },
    { "atan", FunctionId::Atan },
    { "floor", FunctionId::Floor },
    { "ceil", FunctionId::Ceil },
    { "min", FunctionId::Min },
    { "max", FunctionId::Max },
    { "atan2", FunctionId::Atan2 } };
  const auto it = builtins.find(op);
  return it == builtins.end() ? std::nullopt : std::optional<FunctionId>(it->second);
}

/// Emits the statements of one instruction (not const or var-*).
void emit_instruction(Emitter& e, std::string_view o)
{
  using ast::BinaryOp;
  if (o == "neg")
  {
    e.result(e.neg(e.arg(0)));
  }
  else if (o == "square")
  {
    e.result(e.bin(BinaryOp::Mul, e.arg(0), e.arg(0)));
  }
  else if (o == "recip")
  {
    e.result(e.bin(BinaryOp::Div, e.num(1.0), e.arg(0)));
  }
  else if (o == "round")
  {
    emit_round(e);
  }
  else if (o == "compare")
  {
    emit_compare(e);
  }
  else if (o == "mod")
  {
    emit_mod(e);
  }
  else if (o == "and" || o == "or" || o == "not")
  {
    emit_logic(e, o);
  }
  else if (const auto f = builtin_of(o))
  {
    e.result(
      o == "min" || o == "max" || o == "atan2" ? e.fn(*f, e.arg(0), e.arg(1)) : e.fn(*f, e.arg(0)));
  }
  else
  {
    const BinaryOp b = o == "add"   ? BinaryOp::Add
                       : o == "sub" ? BinaryOp::Sub
                       : o == "mul" ? BinaryOp::Mul
                                    : BinaryOp::Div;
    e.result(e.bin(b, e.arg(0), e.arg(1)));
  }
}

struct VmProblem
{
  int column;
  std::string message;
};

// The opcode of a line NAME OPCODE [OPERAND...] and its operand count: `wanted` is the opcode's
// operand count (-2: one number); a problem for an unknown opcode or a wrong count.
std::optional<VmProblem> check_operands(const std::vector<Token>& tokens, int& wanted)
{
  const Token& op = tokens[1];
  wanted = operand_count_of(op.text);
  if (wanted == -1)
  {
    const bool fidget_random = op.text == "rand" || op.text == "mix";
    return VmProblem{ op.column,
      "unknown opcode '" + std::string(op.text) + "'" +
        (fidget_random ? " (Fidget's pseudo-random opcodes hash f32 bit patterns: not supported)"
                       : "") +
        " (known: " + kKnownOpcodes + ")" };
  }
  const std::size_t given = tokens.size() - 2;
  const std::size_t expected = wanted == -2 ? 1 : static_cast<std::size_t>(wanted);
  if (given != expected)
  {
    const Token& where = given > expected ? tokens[2 + expected] : op;
    return VmProblem{ where.column,
      "'" + std::string(op.text) + "' takes " + std::to_string(expected) +
        (wanted == -2     ? " number"
          : expected == 1 ? " operand"
                          : " operands") +
        ", found " + std::to_string(given) };
  }
  return std::nullopt;
}

// A finite decimal number, the whole token (a leading '+' allowed); nullopt otherwise.
std::optional<double> finite_number(std::string_view text)
{
  double c = 0;
  const char* first = text.data();
  const char* stop = first + text.size();
  if (first != stop && *first == '+')
  {
    ++first; // from_chars takes no '+'; a leading '+' is still a number
  }
  const auto [ptr, ec] = std::from_chars(first, stop, c);
  if (ec != std::errc() || ptr != stop || !std::isfinite(c))
  {
    return std::nullopt;
  }
  return c;
}

} // namespace

bool is_vm_file(std::string_view file_name)
{
  if (file_name.size() < 3)
  {
    return false;
  }
  const std::string_view ext = file_name.substr(file_name.size() - 3);
  return ext[0] == '.' && std::tolower(static_cast<unsigned char>(ext[1])) == 'v' &&
         std::tolower(static_cast<unsigned char>(ext[2])) == 'm';
}

ParseResult parse_vm(std::string_view text, std::string file_name)
{
  ParseResult result;
  const auto fail = [&](int line, int column, std::string message)
  {
    result.diagnostics.push_back({ file_name, { line, column }, std::move(message) });
    return std::move(result);
  };
  ast::Object object;
  object.name = std::string(ast::default_object_name);
  object.location = { 1, 1 };
  object.a_dim = 1;
  object.s_dim = 1;
  std::unordered_map<std::string, std::pair<int, int>> names; // name -> (scalar, line)
  HelperPool helpers;
  int x_dim = 0;
  int last = -1;
  SourceLocation last_at;
  int line_number = 0;
  std::size_t begin = 0;
  while (begin <= text.size())
  {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos)
    {
      end = text.size();
    }
    std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r')
    {
      line.remove_suffix(1);
    }
    const std::vector<Token> tokens = split_line(line);
    if (tokens.empty() || tokens[0].text.front() == '#')
    {
      if (end == text.size())
      {
        break;
      }
      continue;
    }
    if (tokens.size() < 2)
    {
      return fail(line_number,
        tokens[0].column,
        "expected NAME OPCODE [OPERAND...], found only '" + std::string(tokens[0].text) + "'");
    }
    const Token& op = tokens[1];
    const SourceLocation at{ line_number, op.column };
    int wanted = 0;
    if (const std::optional<VmProblem> problem = check_operands(tokens, wanted))
    {
      return fail(line_number, problem->column, problem->message);
    }
    ast::ExprPtr value; // const and var-*; the others emit their own statements
    std::vector<int> operands;
    if (wanted == -2)
    {
      const Token& t = tokens[2];
      const std::optional<double> c = finite_number(t.text);
      if (!c)
      {
        return fail(line_number, t.column, "not a finite number: '" + std::string(t.text) + "'");
      }
      value = number(at, *c);
    }
    else
    {
      for (std::size_t k = 2; k < tokens.size(); ++k)
      {
        const auto it = names.find(std::string(tokens[k].text));
        if (it == names.end())
        {
          return fail(line_number,
            tokens[k].column,
            "'" + std::string(tokens[k].text) + "' is not the name of an earlier instruction");
        }
        operands.push_back(it->second.first);
      }
      const std::string_view o = op.text;
      if (o == "var-x" || o == "var-y" || o == "var-z")
      {
        const int k = o == "var-x" ? 0 : o == "var-y" ? 1 : 2;
        x_dim = std::max(x_dim, k + 1);
        value = coordinate(at, k);
      }
    }
    const std::string name(tokens[0].text);
    if (const auto it = names.find(name); it != names.end())
    {
      return fail(line_number,
        tokens[0].column,
        "'" + name + "' is defined twice (first on line " + std::to_string(it->second.second) +
          ")");
    }
    const int index = static_cast<int>(object.scalars.size());
    object.scalars.push_back(name);
    names.emplace(name, std::make_pair(index, line_number));
    if (value)
    {
      object.body.push_back(assign({ line_number, tokens[0].column }, index, std::move(value)));
    }
    else
    {
      Emitter emitter(
        object, helpers, at, { line_number, tokens[0].column }, index, std::move(operands));
      emit_instruction(emitter, op.text);
    }
    last = index;
    last_at = { line_number, tokens[0].column };
    if (end == text.size())
    {
      break;
    }
  }
  if (last < 0)
  {
    return fail(
      1, 1, "no instruction: a .vm file needs at least one line NAME OPCODE [OPERAND...]");
  }
  object.x_dim = std::max(x_dim, 1);
  // The tape is negative inside; FRep's F is positive inside.
  object.result = make(last_at, ast::UnaryExpr{ ast::UnaryOp::Minus, scalar(last_at, last) });
  object.result_location = last_at;
  auto program = std::make_shared<ast::Program>();
  program->file = file_name;
  program->objects.push_back(std::move(object));
  result.program = std::move(program);
  return result;
}

} // namespace frep
