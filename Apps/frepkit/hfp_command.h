// frepkit hfp ...: a drop-in replacement of the HyperFun polygonizer's command line (hfp), with
// FRepKit's mesher behind it (watertight, outward-oriented meshes; -x always honoured). The
// arguments are parsed by hfp_arguments; this runs them: mesh -> -wrl/-stl/-stlb/-pov files, or
// -cli layers, hfp's messages and its last line "triangles: N".
#pragma once

#include <string>
#include <vector>

namespace frepkit
{

/// `args` are the arguments after "hfp". Returns the exit code: 0 ok, 1 an error hfp reported
/// (no model, unreadable or bad model, "Isosurface not generated."). Throws UserError too.
int run_hfp(const std::vector<std::string>& args);

} // namespace frepkit
