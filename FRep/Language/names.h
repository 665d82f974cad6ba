// What a HyperFun name is: letters, digits and '_', starting with a letter, compared without
// case (the original folds names to lower case). One place for the rule: the AST's object
// lookup, the user-function registry, and the engine's text writers (Morph, Project).
#pragma once

#include <string>
#include <string_view>

namespace frep
{

/// `text` in lower case (ASCII).
std::string lower_case(std::string_view text);

/// Letters, digits and '_', starting with a letter (ASCII); not empty.
bool is_identifier(std::string_view text);

} // namespace frep
