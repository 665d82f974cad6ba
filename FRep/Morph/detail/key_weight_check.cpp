#include "Morph/detail/key_weight_check.h"

#include "Language/names.h"

#include <algorithm>
#include <cctype>

namespace frep::morph::detail
{
namespace
{

// Compiles the expression in the statement the text writes (weight_text.cpp's
// key_weight_statements), inside an object of the morph's x[] and a[] with mx[1..d]; a problem
// is reported at the expression's own column ("key weight 'cat':1:7: ...").
void check_expression(const KeyWeight& weight,
  int d,
  int x_dim,
  int a_dim,
  const LoadOptions& key_options,
  std::vector<Diagnostic>& diagnostics)
{
  const std::string where = "key weight '" + weight.key + "'";
  if (weight.expression.find_first_of(";\n\r") != std::string::npos)
  {
    diagnostics.push_back({ where, { 1, 1 }, "a key weight is one expression (no ';' or new line)" });
    return;
  }
  const std::string prefix = "  mg = max(";
  std::string text = "mkw(x[" + std::to_string(x_dim) + "], a[" + std::to_string(a_dim) +
                     "])\n{\n  array mx[" + std::to_string(d) + "];\n";
  for (int i = 1; i <= d; ++i)
    text += "  mx[" + std::to_string(i) + "] = x[" + std::to_string(i) + "];\n";
  const int line = 4 + d;
  text += prefix + weight.expression + ", 0.001);\n  mkw = mg;\n}\n";
  LoadOptions options = key_options;
  options.object = "mkw";
  const LoadedModel loaded = load_model(ModelSource::from_text(text, where), options);
  if (loaded.ok())
    return;
  for (Diagnostic diagnostic : loaded.diagnostics)
  {
    diagnostic.file = where;
    if (diagnostic.location.line == line)
      diagnostic.location = { 1,
        std::max(1, diagnostic.location.column - static_cast<int>(prefix.size())) };
    else
      diagnostic.location = {};
    diagnostics.push_back(std::move(diagnostic));
  }
  if (loaded.diagnostics.empty())
    diagnostics.push_back({ where, {}, loaded.message() });
}

} // namespace

std::vector<std::string> key_weight_expressions(const MorphSpec& spec,
  const std::vector<std::string>& key_names,
  int d,
  int a_dim,
  const LoadOptions& key_options,
  std::vector<Diagnostic>& diagnostics)
{
  if (spec.key_weights.empty())
    return {};
  const std::size_t before = diagnostics.size();
  if (spec.scheme == Interpolation::CatmullRom)
    diagnostics.push_back({ "metamorphosis",
      {},
      "key weights need a scheme whose weights are never negative (linear or b-spline): "
      "Catmull-Rom's go below 0, and their weighted sum could vanish" });
  const int x_dim = d + static_cast<int>(spec.lattice.size());
  std::vector<std::string> expressions(key_names.size());
  std::vector<std::string> named;
  for (const KeyWeight& weight : spec.key_weights)
  {
    const std::string key = lower_case(weight.key);
    if (std::find(named.begin(), named.end(), key) != named.end())
    {
      diagnostics.push_back(
        { "metamorphosis", {}, "the key '" + weight.key + "' is given two weights" });
      continue;
    }
    named.push_back(key);
    if (std::find(key_names.begin(), key_names.end(), key) == key_names.end())
    {
      diagnostics.push_back({ "metamorphosis",
        {},
        "a weight for '" + weight.key + "', which is not one of the keys' objects" });
      continue;
    }
    check_expression(weight, d, x_dim, a_dim, key_options, diagnostics);
    for (std::size_t k = 0; k < key_names.size(); ++k)
      if (key_names[k] == key)
        expressions[k] = "(" + weight.expression + ")";
  }
  return diagnostics.size() == before ? expressions : std::vector<std::string>{};
}

} // namespace frep::morph::detail
