// The original HyperFun interpreter and polygonizer (pmur002/hyperfun src/, built without R by
// CMakeLists.txt), through their own C++ classes:
//
//   hyperfun_driver eval MODEL.hf OBJECT POINTS.bin COUNT VALUES.bin [REPEAT]
//       HFInterpreter::calc, one point per call, one thread, on the first COUNT points;
//   hyperfun_driver mesh MODEL.hf OBJECT x0,y0,z0,x1,y1,z1 SAMPLES
//       what `hfp MODEL -usedc 0 -b BOX -g SAMPLES-1 -o OBJECT` does (marching cubes: g cells =
//       g+1 samples per axis), with hfp's own defaults from its command-line class, except that
//       the grid is set after parsing: hfp clamps -g to 250, and 256 samples need g = 255.
//
// Prints one line "RESULT key=value ..." for run_peers.sh.
#include "points.h"

#include <hfinterpreter.h> // the original's sources (external: the user names them)
#include <hfpcommandline.h>
#include <hfpolymesh.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

std::string read_model(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot read " + path);
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str() + '\0'; // as hfp's CMainApp::readFile
}

void parse(HFInterpreter& interpreter, const std::string& model, const std::string& object)
{
  try
  {
    interpreter.parse(read_model(model), object);
  }
  catch (const ParseError& e)
  {
    throw std::runtime_error(model + ": " + e.error + " (line " + std::to_string(e.line) + ")");
  }
  catch (const MemoryError& e)
  {
    throw std::runtime_error(model + ": memory error " + e.error);
  }
}

int eval(int argc, char** argv)
{
  if (argc < 7)
  {
    throw std::runtime_error("usage: hyperfun_driver eval MODEL OBJECT POINTS COUNT VALUES [REPEAT]");
  }
  const peers::Points points = peers::read_points(argv[4]);
  const std::size_t count = std::min<std::size_t>(std::stoul(argv[5]), points.count());
  const int repeat = argc > 7 ? std::max(1, std::stoi(argv[7])) : 3;
  HFInterpreter interpreter;
  parse(interpreter, argv[2], argv[3]);
  std::vector<double> s(std::max<int>(1, interpreter.getSSize()) + 8, 0.0);
  std::vector<double> x(3), values(count);
  std::vector<double> times;
  // At least `repeat` passes and at least half a second in all (short passes are noisy).
  const auto all_start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeat || peers::seconds_since(all_start) < 0.5; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < count; ++i)
    {
      x[0] = points.xyz[3 * i];
      x[1] = points.xyz[3 * i + 1];
      x[2] = points.xyz[3 * i + 2];
      values[i] = interpreter.calc(x, s.data());
    }
    times.push_back(peers::seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  const double t = times[times.size() / 2];
  peers::write_values(argv[6], values);
  std::printf("RESULT points=%zu seconds=%.6g mpps=%.4g\n", count, t, count / t / 1e6);
  return 0;
}

int mesh(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: hyperfun_driver mesh MODEL OBJECT BOX SAMPLES");
  }
  double lo[3], hi[3];
  peers::parse_box(argv[4], lo, hi);
  const int cells = std::stoi(argv[5]) - 1;
  const auto start = std::chrono::steady_clock::now();
  // hfp's defaults for everything, from its own parser.
  char box[256];
  std::snprintf(box, sizeof box, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", lo[0], lo[1], lo[2], hi[0],
    hi[1], hi[2]);
  std::vector<std::string> args = { "hfp", argv[2], "-usedc", "0", "-b", box, "-o", argv[3] };
  std::vector<char*> cargs;
  for (std::string& a : args)
  {
    cargs.push_back(a.data());
  }
  int cargc = static_cast<int>(cargs.size());
  HFPCommandLine cl(cargc, cargs.data());
  cl.itsGridSize = { cells, cells, cells };
  HFInterpreter interpreter;
  parse(interpreter, cl.itsModel, cl.itsObject);
  HFPolyMesh polygonizer(interpreter);
  polygonizer.Timer(false);
  polygonizer.IsoValue(cl.itsIsoValue);
  polygonizer.MinMax(cl.itsBBMinMax);
  polygonizer.Grid(cl.itsGridSize);
  polygonizer.DimMap(cl.itsXYZMapping);
  polygonizer.Constants(cl.itsXConstants);
  polygonizer.Parameters(cl.itsAConstants);
  polygonizer.Normals(cl.itsNormals);
  polygonizer.Search(cl.itsSearch);
  polygonizer.SearchPercent(cl.itsSearchPer);
  polygonizer.Reduce(cl.itsReduce);
  polygonizer.Refine(cl.itsAttributes);
  polygonizer.Calc();
  const double t = peers::seconds_since(start);
  std::printf("RESULT samples=%d seconds=%.6g triangles=%d\n", cells + 1, t,
    polygonizer.TriangleNum());
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "eval")
    {
      return eval(argc, argv);
    }
    if (command == "mesh")
    {
      return mesh(argc, argv);
    }
    std::fprintf(stderr, "usage: hyperfun_driver eval|mesh ... (see the source)\n");
    return 2;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "hyperfun_driver: %s\n", e.what());
    return 1;
  }
}
