#include "Language/vm_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
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

/// Operands each opcode takes (-1: unknown opcode).
int operand_count_of(std::string_view op)
{
  static const std::unordered_map<std::string_view, int> counts = {
    { "const", -2 }, { "var-x", 0 }, { "var-y", 0 }, { "var-z", 0 }, { "neg", 1 },
    { "square", 1 }, { "sqrt", 1 }, { "abs", 1 }, { "add", 2 }, { "sub", 2 }, { "mul", 2 },
    { "div", 2 }, { "min", 2 }, { "max", 2 } };
  const auto it = counts.find(op);
  return it == counts.end() ? -1 : it->second;
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
      return fail(line_number, tokens[0].column,
        "expected NAME OPCODE [OPERAND...], found only '" + std::string(tokens[0].text) + "'");
    }
    const Token& op = tokens[1];
    const SourceLocation at{ line_number, op.column };
    const int wanted = operand_count_of(op.text);
    if (wanted == -1)
    {
      return fail(line_number, op.column,
        "unknown opcode '" + std::string(op.text) +
          "' (known: const var-x var-y var-z neg square sqrt abs add sub mul div min max)");
    }
    const std::size_t given = tokens.size() - 2;
    const std::size_t expected = wanted == -2 ? 1 : static_cast<std::size_t>(wanted);
    if (given != expected)
    {
      const Token& where = given > expected ? tokens[2 + expected] : op;
      return fail(line_number, where.column,
        "'" + std::string(op.text) + "' takes " + std::to_string(expected) +
          (wanted == -2 ? " number" : expected == 1 ? " operand" : " operands") + ", found " +
          std::to_string(given));
    }
    std::vector<ast::ExprPtr> operands;
    ast::ExprPtr value;
    if (wanted == -2)
    {
      const Token& t = tokens[2];
      double c = 0;
      const char* first = t.text.data();
      const char* stop = first + t.text.size();
      if (*first == '+')
      {
        ++first; // from_chars takes no '+'; a leading '+' is still a number
      }
      const auto [ptr, ec] = std::from_chars(first, stop, c);
      if (ec != std::errc() || ptr != stop || !std::isfinite(c))
      {
        return fail(line_number, t.column, "not a finite number: '" + std::string(t.text) + "'");
      }
      value = number(at, c);
    }
    else
    {
      for (std::size_t k = 2; k < tokens.size(); ++k)
      {
        const auto it = names.find(std::string(tokens[k].text));
        if (it == names.end())
        {
          return fail(line_number, tokens[k].column,
            "'" + std::string(tokens[k].text) + "' is not the name of an earlier instruction");
        }
        operands.push_back(scalar({ line_number, tokens[k].column }, it->second.first));
      }
      const std::string_view o = op.text;
      if (o == "var-x" || o == "var-y" || o == "var-z")
      {
        const int k = o == "var-x" ? 0 : o == "var-y" ? 1 : 2;
        x_dim = std::max(x_dim, k + 1);
        value = coordinate(at, k);
      }
      else if (o == "neg")
      {
        value = make(at, ast::UnaryExpr{ ast::UnaryOp::Minus, std::move(operands[0]) });
      }
      else if (o == "square")
      {
        const int s = std::get<ast::ScalarExpr>(operands[0]->node).scalar;
        value = binary(at, ast::BinaryOp::Mul, std::move(operands[0]), scalar(at, s));
      }
      else if (o == "sqrt" || o == "abs")
      {
        value = call(at, o == "sqrt" ? FunctionId::Sqrt : FunctionId::Abs, std::move(operands));
      }
      else if (o == "min" || o == "max")
      {
        value = call(at, o == "min" ? FunctionId::Min : FunctionId::Max, std::move(operands));
      }
      else
      {
        const ast::BinaryOp b = o == "add" ? ast::BinaryOp::Add
          : o == "sub"                     ? ast::BinaryOp::Sub
          : o == "mul"                     ? ast::BinaryOp::Mul
                                           : ast::BinaryOp::Div;
        value = binary(at, b, std::move(operands[0]), std::move(operands[1]));
      }
    }
    const std::string name(tokens[0].text);
    if (const auto it = names.find(name); it != names.end())
    {
      return fail(line_number, tokens[0].column,
        "'" + name + "' is defined twice (first on line " + std::to_string(it->second.second) + ")");
    }
    const int index = static_cast<int>(object.scalars.size());
    object.scalars.push_back(name);
    names.emplace(name, std::make_pair(index, line_number));
    ast::Stmt stmt;
    stmt.location = { line_number, tokens[0].column };
    stmt.node = ast::AssignScalar{ index, std::move(value) };
    object.body.push_back(std::move(stmt));
    last = index;
    last_at = { line_number, tokens[0].column };
    if (end == text.size())
    {
      break;
    }
  }
  if (last < 0)
  {
    return fail(1, 1, "no instruction: a .vm file needs at least one line NAME OPCODE [OPERAND...]");
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
