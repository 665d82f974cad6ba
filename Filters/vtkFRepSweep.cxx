#include "vtkFRepSweep.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include "Project/projection.h"
#include "Project/sweep_model.h"

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkFRepSweep);

namespace
{

frep::project::SweepPath MakePath(const std::vector<std::array<double, 3>>& points, int curve,
  bool closed, int orientation)
{
  frep::project::SweepPath path;
  path.points = points;
  path.curve = curve == vtkFRepSweep::CATMULL_ROM ? frep::project::SweepPath::Curve::CatmullRom
                                                  : frep::project::SweepPath::Curve::Polyline;
  path.closed = closed;
  path.orientation = orientation == vtkFRepSweep::TANGENT
    ? frep::project::SweepPath::Orientation::Tangent
    : frep::project::SweepPath::Orientation::Fixed;
  return path;
}

// The output's ranges: the input's free coordinates' ranges swept along the path.
std::array<frep::Interval, 3> SweptRanges(
  const frep::project::SweepPath& path, const std::vector<std::array<double, 2>>& ranges)
{
  std::array<frep::Interval, 3> box;
  for (std::size_t a = 0; a < 3; ++a)
  {
    box[a] = { ranges[a][0], ranges[a][1] };
  }
  return frep::project::sweep_bounds(path, box);
}

} // namespace

//------------------------------------------------------------------------------
vtkFRepSweep::vtkFRepSweep()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepSweep::~vtkFRepSweep() = default;

//------------------------------------------------------------------------------
void vtkFRepSweep::AddPathPoint(double x, double y, double z)
{
  this->PathPoints.push_back({ x, y, z });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepSweep::RemoveAllPathPoints()
{
  if (!this->PathPoints.empty())
  {
    this->PathPoints.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkFRepSweep::GetPathPoint(int i, double point[3]) const
{
  const bool in = i >= 0 && i < this->GetNumberOfPathPoints();
  for (int a = 0; a < 3; ++a)
  {
    point[a] = in ? this->PathPoints[static_cast<std::size_t>(i)][a]
                  : std::numeric_limits<double>::quiet_NaN();
  }
}

//------------------------------------------------------------------------------
std::string vtkFRepSweep::Problems(int free) const
{
  std::string problems;
  const auto add = [&problems](const std::string& p) { problems += "\n  " + p; };
  if (free != 3)
  {
    add("the profile must have 3 free coordinates (it has " + std::to_string(free) + ")");
  }
  const std::string path = frep::project::sweep_path_error(
    MakePath(this->PathPoints, this->Curve, this->Closed, this->Orientation));
  if (!path.empty())
  {
    add(path);
  }
  if (!(this->Tolerance > 0.0))
  {
    add("Tolerance must be > 0");
  }
  if (!(this->Band > this->Tolerance))
  {
    add("Band must be greater than Tolerance");
  }
  return problems;
}

//------------------------------------------------------------------------------
int vtkFRepSweep::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  // From the input's keys and the path alone: nothing upstream is executed.
  vtkFRepInformation::Metadata in;
  if (!vtkFRepInformation::Get(inInfo[0]->GetInformationObject(0), in) ||
    !this->Problems(in.GetDimension()).empty())
  {
    return 1; // an empty input is quiet; RequestData reports the problems, once
  }
  std::vector<std::array<double, 2>> ranges;
  vtkFRepInformation::Metadata out;
  for (const int c : in.FreeCoordinates)
  {
    out.Names.push_back(in.Names[static_cast<std::size_t>(c)]);
    ranges.push_back(in.Ranges[static_cast<std::size_t>(c)]);
  }
  const auto box = SweptRanges(
    MakePath(this->PathPoints, this->Curve, this->Closed, this->Orientation), ranges);
  for (int a = 0; a < 3; ++a)
  {
    out.Ranges.push_back({ box[a].lo, box[a].hi });
    out.FixedValues.push_back(std::numeric_limits<double>::quiet_NaN());
    out.FreeCoordinates.push_back(a);
  }
  out.ObjectName = "projection"; // the name project() gives a composed model's projection
  vtkFRepInformation::Set(outInfo->GetInformationObject(0), out);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepSweep::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkFRepObject* input = vtkFRepObject::GetData(inInfo[0]);
  vtkFRepObject* output = vtkFRepObject::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkFRepObject");
    return 0;
  }
  output->Initialize();
  if (!input || !input->HasModel())
  {
    vtkDebugMacro(<< "empty input: empty output");
    return 1;
  }
  std::string problems = this->Problems(input->GetDimension());
  const frep::project::SweepPath path =
    MakePath(this->PathPoints, this->Curve, this->Closed, this->Orientation);
  frep::LoadedModel swept;
  if (problems.empty())
  {
    const frep::LoadedModel moved =
      frep::project::sweep_model({ input->GetModel(), input->GetSpecialisation() }, path);
    frep::project::ProjectionOptions options;
    options.tolerance = this->Tolerance;
    options.band = this->Band;
    swept = moved.ok() ? frep::project::project(moved.model, { { 4, 0.0, 1.0 } }, options) : moved;
    if (!swept.ok())
    {
      problems += "\n  " + swept.message();
    }
  }
  if (!problems.empty())
  {
    vtkErrorMacro(<< "cannot sweep " << input->GetObjectName() << " (the output is empty):"
                  << problems);
    return 1;
  }
  output->SetModel(swept.model);
  std::vector<std::array<double, 2>> ranges;
  for (int a = 0; a < 3; ++a)
  {
    double range[2];
    input->GetCoordinateRange(input->GetFreeCoordinate(a), range);
    ranges.push_back({ range[0], range[1] });
  }
  const auto box = SweptRanges(path, ranges);
  for (int a = 0; a < 3; ++a)
  {
    output->SetCoordinateName(a, input->GetCoordinateName(input->GetFreeCoordinate(a)));
    output->SetCoordinateRange(a, box[a].lo, box[a].hi);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepSweep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathPoints:";
  for (const auto& p : this->PathPoints)
  {
    os << " (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  }
  os << "\n";
  os << indent << "Curve: " << (this->Curve == CATMULL_ROM ? "CatmullRom" : "Polyline") << "\n";
  os << indent << "Closed: " << (this->Closed ? "On" : "Off") << "\n";
  os << indent << "Orientation: " << (this->Orientation == TANGENT ? "Tangent" : "Fixed") << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "Band: " << this->Band << "\n";
}
