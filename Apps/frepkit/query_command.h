// frepkit query contact|presence|volume: questions asked of space-time models (FRep/Project's
// space_time.h), one coordinate of which is time (--time x4=0:1).
//   contact A.hf B.hf   the first time the two moving solids share a point of --box, and where
//   presence MODEL.hf   the time intervals during which the point --at is inside
//   volume MODEL.hf     the section's volume (or area) at --steps times, a table (CSV with -o)
//   topology MODEL.hf   the section's pieces and genus at --steps times, and where they change
#pragma once

#include "user_inputs.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct QueryOptions
{
  UserInputs user; ///< --library, --shape
  std::string question;        ///< contact, presence, volume
  std::vector<std::string> models;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::string time;            ///< --time x4=0:1
  std::vector<std::string> box; ///< --box over the coordinates besides time
  std::vector<double> at;      ///< --at: the point, without its time coordinate
  double time_tolerance = 1e-4;
  int steps = 11;
  int grid = 64;
  std::string output = "-";
};

CLI::App* add_query_command(CLI::App& app, QueryOptions& options);

/// Prints the answer; 0 when asked, UserError for bad input.
int run_query(const QueryOptions& options);

} // namespace frepkit
