// The original interpreter's run-time error texts (int_global.c Error_Strings[]), verbatim: the
// conformance suite and users' scripts compare them character for character.
#pragma once

namespace frep::messages
{

inline constexpr const char* kNotInitialized = "Not initialized variable";
inline constexpr const char* kDivisionByZero = "Division by zero";
inline constexpr const char* kNegativePowerBase = "Negative value for power";
inline constexpr const char* kZeroPowerBase = "Zero value in negative or zero power";
inline constexpr const char* kNegativeSqrt = "Negative value for square root";
inline constexpr const char* kNegativeLog = "Negative for log function";
inline constexpr const char* kAsinAcosRange = "Argument must be in range -1.0 .. +1.0";
inline constexpr const char* kTanArgument = "Cannot compute tan for this argument";
inline constexpr const char* kIndexOutOfRange = "Array index out of range";
/// Reading an element of a local array that was never assigned in this evaluation.
inline constexpr const char* kUnassignedElement = "Unassigned identificator used in expression";
/// Passing a local array with an unassigned element to a library function or an object.
inline constexpr const char* kUnassignedArray = "Some items of array are unassigned";

} // namespace frep::messages
