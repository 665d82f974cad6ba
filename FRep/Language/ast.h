// Abstract syntax tree of a HyperFun program, as the parser produces it. Names are resolved:
// scalars and local arrays are slots of their object, functions are FunctionIds, called objects
// are indices of earlier objects. Every node keeps the source position that run-time errors of
// the original interpreter report for it.
#pragma once

#include "function_table.h"
#include "source_location.h"
#include "user_functions.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace frep::ast
{

/// Which array a name refers to.
enum class ArrayKind : std::uint8_t
{
  X,    ///< the point coordinates x[1..x_dim]
  A,    ///< the parameters a[1..a_dim]
  S,    ///< the attributes s[1..s_dim]
  Local ///< a local `array` of the object
};

/// A whole-array reference (library array argument, object call argument, element access).
struct ArrayName
{
  ArrayKind kind = ArrayKind::X;
  int local = -1;          ///< index into Object::arrays when kind == Local
  SourceLocation location; ///< position of the name
};

enum class UnaryOp : std::uint8_t
{
  Plus,   ///< +e
  Minus,  ///< -e
  Negate  ///< ~e (set complement; numerically -e)
};

enum class BinaryOp : std::uint8_t
{
  Add, Sub, Mul, Div, Pow,
  Union,     ///< |  f1 + f2 + sqrt(f1^2 + f2^2)
  Intersect, ///< &  f1 + f2 - sqrt(f1^2 + f2^2)
  Subtract,  ///< \  f1 - f2 - sqrt(f1^2 + f2^2)
  Product    ///< @  identical to & in the original
};

/// Comparisons, only inside conditions; value 1.0 or 0.0 (= and /= use the 1e-6 tolerance).
enum class CompareOp : std::uint8_t
{
  Eq, Ne, Lt, Le, Gt, Ge
};

/// Logical connectives, only inside conditions; operands true iff |v| >= 1e-6.
enum class LogicOp : std::uint8_t
{
  And, Or
};

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct NumberExpr
{
  double value = 0; ///< the value the original's scanner computes (not always correctly rounded)
};

/// A local scalar variable.
struct ScalarExpr
{
  int scalar = -1; ///< index into Object::scalars
};

/// v[i] for x, a, s or a local array. Index = HF_round(i), 1-based.
struct ElementExpr
{
  ArrayName array;
  ExprPtr index;
  /// Unused by the interpreter: for a READ the original reports "Array index out of range" at
  /// the position of the first instruction of the index expression's postfix code (its leftmost
  /// innermost operand: `v[k+1]` -> k, `v[x[1]]` -> 1), which the interpreter derives from the
  /// index expression itself.
  SourceLocation index_end;
};

struct UnaryExpr
{
  UnaryOp op = UnaryOp::Minus;
  ExprPtr operand;
};

struct BinaryExpr
{
  BinaryOp op = BinaryOp::Add;
  ExprPtr lhs;
  ExprPtr rhs;
};

struct CompareExpr
{
  CompareOp op = CompareOp::Eq;
  ExprPtr lhs;
  ExprPtr rhs;
};

struct LogicExpr
{
  LogicOp op = LogicOp::And;
  ExprPtr lhs;
  ExprPtr rhs;
};

struct NotExpr
{
  ExprPtr operand;
};

/// One argument of a builtin/library call; which alternative is set follows the function's
/// ArgKind for that position.
using CallArg = std::variant<ExprPtr, ArrayName, std::string>;

/// A builtin or library function call, arguments in source order (the original evaluates them
/// last-to-first).
struct CallExpr
{
  FunctionId function = FunctionId::Sqrt;
  std::vector<CallArg> args;
};

/// A call of a user function (user_functions.h): `function` indexes the registry the program
/// was parsed with (Program::user_functions). Arguments in source order, each a real or an
/// array as the function's kinds say; evaluated last to first like a library call's.
struct UserCallExpr
{
  int function = -1;
  std::vector<CallArg> args;
};

/// A call of an earlier object of the same file: OBJ(xarr, aarr [, sarr]). Sizes are checked by
/// the parser. Without the third argument the caller's own s[] is passed.
struct ObjectCallExpr
{
  int object = -1; ///< index into Program::objects (always less than the caller's index)
  ArrayName x;
  ArrayName a;
  std::optional<ArrayName> s;
  /// The closing ')'. When s is omitted the original attaches this position to its implicit
  /// third argument, so it is where "Some items of array are unassigned" is reported for an
  /// a[] argument with unassigned items (and the position of an out-of-range index whose
  /// expression starts with such a call).
  SourceLocation close_paren;
};

/// An expression node. `location` is the position the original attaches to the node's
/// instruction: the operator for unary/binary/compare/logic nodes, the function or object name
/// for calls, the name for variables and elements, the literal for numbers.
struct Expr
{
  SourceLocation location;
  std::variant<NumberExpr, ScalarExpr, ElementExpr, UnaryExpr, BinaryExpr, CompareExpr,
    LogicExpr, NotExpr, CallExpr, ObjectCallExpr, UserCallExpr>
    node;
};

struct Stmt;
using Block = std::vector<Stmt>;

/// NAME = expr;
struct AssignScalar
{
  int scalar = -1;
  ExprPtr value;
};

/// NAME[i] = expr;  or  s[i] = expr;
struct AssignElement
{
  ArrayName array; ///< Local or S
  ExprPtr index;
  /// The FIRST token of the index expression, an opening parenthesis included: the original
  /// reports "Array index out of range" for a WRITE there (`v[x[1]] = 9;` -> x; `v[(k)]` -> the
  /// '('). (Despite the name; kept for compatibility.)
  SourceLocation index_end;
  ExprPtr value;
};

/// NAME = [lit, ...];  or  s = [lit, ...];  (exactly as many literals as the array has items)
struct AssignArray
{
  ArrayName array; ///< Local or S
  std::vector<double> values;
};

/// if cond then ... [else ...] endif;
struct IfStmt
{
  ExprPtr condition;
  Block then_block;
  Block else_block;
};

/// while cond loop ... endloop;
struct WhileStmt
{
  ExprPtr condition;
  Block body;
};

struct Stmt
{
  SourceLocation location; ///< first token of the statement
  std::variant<AssignScalar, AssignElement, AssignArray, IfStmt, WhileStmt> node;
};

struct LocalArray
{
  std::string name; ///< lower-case
  int size = 0;     ///< > 0
  SourceLocation location;
};

struct Object
{
  std::string name; ///< lower-case, as the original stores it
  /// The file the object was read from: the program's own file, or a HyperFun library file
  /// (ParseOptions::libraries) whose objects the program calls like its own. Run-time errors
  /// inside the object name this file.
  std::string file;
  SourceLocation location;
  int x_dim = 0;
  int a_dim = 0;     ///< may be 0
  int s_dim = 1;     ///< 1 when the header has no s[..]
  /// Whether the header declares s[..]; without it the object has s[1] all the same, as in the
  /// original HyperFun (its interpreter always allocates s[1]).
  bool s_declared = false;
  std::vector<LocalArray> arrays;
  std::vector<std::string> scalars; ///< lower-case names, in order of first assignment
  Block body;                       ///< statements before the final NAME = expr;
  ExprPtr result;                   ///< the final expression
  SourceLocation result_location;   ///< position of the final NAME
};

struct Program
{
  std::string file;             ///< for diagnostics
  /// The library files' objects first (in the order the libraries were given), then the file's
  /// own, each in file order; calls only go to earlier objects.
  std::vector<Object> objects;
  /// Index of the file's first own object: the objects before it come from HyperFun library
  /// files (0 without libraries). The default object is chosen among the own objects.
  int first_own_object = 0;
  /// The user functions the program was parsed with (null: none); UserCallExpr indexes it.
  std::shared_ptr<const UserFunctionRegistry> user_functions;
};

/// How select_object compares names.
enum class NameMatch : std::uint8_t
{
  IgnoreCase, ///< FRepKit's rule for users (--object Cat finds cat)
  Exact       ///< the original's strcmp against the lower-case stored names (hfp -o)
};

/// Number of objects the file itself defines (not counting the library files' objects).
int own_object_count(const Program& program);

/// The object the original would evaluate for a requested name (hfinterpreter.cpp): the object
/// called `name`, else the FIRST object of the file (its first own object: library files'
/// objects are only called). Returns -1 only when the file defines no object. With no name from
/// the user, use select_default_object.
int select_object(const Program& program, std::string_view name,
  NameMatch match = NameMatch::IgnoreCase);

/// The name of the object evaluated when none is named (the original's default, hfp -o).
inline constexpr std::string_view default_object_name = "my_model";

/// The object evaluated when none is named: `my_model` (any case) among the file's own objects,
/// else the file's first own object; -1 only when the file defines no object. Every tool and
/// filter uses this one rule.
int select_default_object(const Program& program);

/// Index of the object called `name` (case-insensitive), or -1. Library files' objects are
/// found too (names are unique across the program).
int find_object(const Program& program, std::string_view name);

} // namespace frep::ast
