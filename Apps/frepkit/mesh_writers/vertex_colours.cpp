#include "vertex_colours.h"

#include <algorithm>
#include <cmath>

namespace frepkit
{

std::vector<Rgb> colours_from_attributes(const frep::mesh::Surface& surface)
{
  std::vector<Rgb> colours;
  const std::size_t stride = static_cast<std::size_t>(surface.attribute_count);
  if (stride == 0 || surface.attributes.size() < stride * surface.point_count())
  {
    return colours;
  }
  colours.resize(surface.point_count(), Rgb{ 0, 0, 0 });
  for (std::size_t i = 0; i < colours.size(); ++i)
  {
    for (std::size_t c = 0; c < 3 && c < stride; ++c)
    {
      const float s = surface.attributes[i * stride + c];
      colours[i][c] = std::isnan(s) ? 0.0f : std::clamp(s, 0.0f, 1.0f);
    }
  }
  return colours;
}

bool tape_sets_attributes(const frep::Tape& tape, std::size_t count)
{
  for (std::size_t output = 1; output < tape.outputs.size() && output <= count; ++output)
  {
    const std::uint32_t slot = tape.outputs[output];
    // The last instruction that writes the slot decides what the output is.
    const frep::Instruction* writer = nullptr;
    for (const frep::Instruction& instruction : tape.code)
    {
      if (instruction.op == frep::Opcode::Call)
      {
        // An opaque call (a library function or a whole interpreted object) writes its own
        // output slots.
        const auto& outputs = tape.calls[static_cast<std::size_t>(instruction.index)].outputs;
        if (std::find(outputs.begin(), outputs.end(), slot) != outputs.end())
        {
          writer = &instruction;
        }
      }
      else if (instruction.out == slot && instruction.op != frep::Opcode::ErrorIf)
      {
        writer = &instruction;
      }
    }
    if (writer != nullptr && !(writer->op == frep::Opcode::Const && writer->imm == 0.0))
    {
      return true;
    }
  }
  return false;
}

std::uint8_t colour_byte(float component)
{
  return static_cast<std::uint8_t>(std::lround(std::clamp(component, 0.0f, 1.0f) * 255.0f));
}

} // namespace frepkit
