// A picture or window size on the command line, the same for every program (frepkit render
// --size, FRepStudio --size): WIDTHxHEIGHT or WIDTH,HEIGHT (640x480, 640X480, 640,480).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace frepkit
{

constexpr int kMaxPictureSide = 16384;

struct PictureSize
{
  int width = 0;
  int height = 0;
};

/// `text` as WIDTHxHEIGHT or WIDTH,HEIGHT, each a whole number from 1 to kMaxPictureSide (spaces
/// around the numbers are allowed). On failure returns nullopt and, when `error` is given, a
/// sentence saying what is wanted (without the option's name: the caller adds it).
std::optional<PictureSize> parse_picture_size(std::string_view text, std::string* error = nullptr);

} // namespace frepkit
