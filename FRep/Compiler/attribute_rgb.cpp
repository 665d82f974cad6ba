#include "Compiler/attribute_rgb.h"

#include <algorithm>
#include <cmath>

namespace frep
{

AttributeRgb attribute_rgb(const float* s, std::size_t count)
{
  AttributeRgb rgb{ 0.0f, 0.0f, 0.0f };
  for (std::size_t c = 0; c < 3 && c < count; ++c)
  {
    rgb[c] = std::isnan(s[c]) ? 0.0f : std::clamp(s[c], 0.0f, 1.0f);
  }
  return rgb;
}

std::vector<AttributeRgb> attribute_colours(const std::vector<float>& attributes,
  std::size_t count,
  std::size_t points)
{
  std::vector<AttributeRgb> colours;
  if (count == 0 || attributes.size() < count * points)
  {
    return colours;
  }
  colours.reserve(points);
  for (std::size_t i = 0; i < points; ++i)
  {
    colours.push_back(attribute_rgb(attributes.data() + i * count, count));
  }
  return colours;
}

bool tape_sets_attributes(const Tape& tape, std::size_t count)
{
  for (std::size_t output = 1; output < tape.outputs.size() && output <= count; ++output)
  {
    const std::uint32_t slot = tape.outputs[output];
    // The last instruction that writes the slot decides what the output is.
    const Instruction* writer = nullptr;
    for (const Instruction& instruction : tape.code)
    {
      if (instruction.op == Opcode::Call)
      {
        // An opaque call (a library function or a whole interpreted object) writes its own
        // output slots.
        const auto& outputs = tape.calls[static_cast<std::size_t>(instruction.index)].outputs;
        if (std::find(outputs.begin(), outputs.end(), slot) != outputs.end())
        {
          writer = &instruction;
        }
      }
      else if (instruction.out == slot && instruction.op != Opcode::ErrorIf)
      {
        writer = &instruction;
      }
    }
    if (writer != nullptr && !(writer->op == Opcode::Const && writer->imm == 0.0))
    {
      return true;
    }
  }
  return false;
}

bool tape_sets_colours(const Tape& tape, int s_dim)
{
  return s_dim >= 3 && tape_sets_attributes(tape, 3);
}

std::uint8_t colour_byte(float component)
{
  return static_cast<std::uint8_t>(std::lround(std::clamp(component, 0.0f, 1.0f) * 255.0f));
}

} // namespace frep
