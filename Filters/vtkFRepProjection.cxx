#include "vtkFRepProjection.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include "Project/projection.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkFRepProjection);

//------------------------------------------------------------------------------
vtkFRepProjection::vtkFRepProjection()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepProjection::~vtkFRepProjection() = default;

//------------------------------------------------------------------------------
void vtkFRepProjection::AddProjection(int coordinate, double lo, double hi)
{
  const std::array<double, 2> range{ lo, hi };
  auto it = this->Added.find(coordinate);
  if (it != this->Added.end() && it->second == range)
  {
    return;
  }
  this->Added[coordinate] = range;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepProjection::RemoveAllProjections()
{
  if (!this->Added.empty())
  {
    this->Added.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::map<int, std::array<double, 2>> vtkFRepProjection::Requests(
  const std::vector<double>& fixed, int freeCount, std::vector<std::string>& problems) const
{
  std::map<int, std::array<double, 2>> requests = this->Added;
  if (this->ProjectedCoordinate >= 0)
  {
    if (requests.count(this->ProjectedCoordinate) != 0)
    {
      problems.push_back("coordinate " + std::to_string(this->ProjectedCoordinate) +
        " is both ProjectedCoordinate and added");
    }
    requests[this->ProjectedCoordinate] = { this->ProjectedRange[0], this->ProjectedRange[1] };
  }
  if (requests.empty())
  {
    problems.push_back("no coordinate to project (ProjectedCoordinate is -1, none added)");
  }
  const int n = static_cast<int>(fixed.size());
  for (const auto& [c, range] : requests)
  {
    const std::string name = "x" + std::to_string(c + 1) + " (coordinate " + std::to_string(c) + ")";
    if (c < 0 || c >= n)
    {
      problems.push_back("cannot project along coordinate " + std::to_string(c) +
        ": the model has " + std::to_string(n));
    }
    else if (!std::isnan(fixed[c]))
    {
      problems.push_back(name + " is fixed by the input; project a free coordinate");
    }
    if (!std::isfinite(range[0]) || !std::isfinite(range[1]) || range[0] > range[1])
    {
      problems.push_back(name + "'s range must be finite, lo <= hi");
    }
  }
  if (!(this->Tolerance > 0.0))
  {
    problems.push_back("Tolerance must be > 0");
  }
  if (!(this->Band > this->Tolerance))
  {
    problems.push_back("Band must be greater than Tolerance");
  }
  if (problems.empty() && static_cast<int>(requests.size()) >= freeCount)
  {
    problems.push_back("every free coordinate would be projected: nothing would be left");
  }
  return requests;
}

//------------------------------------------------------------------------------
int vtkFRepProjection::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  // The input's metadata with the projected coordinates fixed: nothing upstream is executed.
  vtkFRepInformation::Metadata metadata;
  if (!vtkFRepInformation::Get(inInfo[0]->GetInformationObject(0), metadata))
  {
    return 1; // an empty input: an empty output, quietly
  }
  std::vector<std::string> problems;
  const auto requests = this->Requests(metadata.FixedValues, metadata.GetDimension(), problems);
  if (!problems.empty())
  {
    return 1; // RequestData reports them, once
  }
  std::vector<int> free;
  for (const int c : metadata.FreeCoordinates)
  {
    if (requests.count(c) == 0)
    {
      free.push_back(c);
    }
  }
  for (const auto& [c, range] : requests)
  {
    metadata.FixedValues[c] = range[0];
  }
  metadata.FreeCoordinates = free;
  metadata.ObjectName += "_projection";
  metadata.Parameters.clear();
  vtkFRepInformation::Set(outInfo->GetInformationObject(0), metadata);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepProjection::RequestData(vtkInformation*,
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
  const int n = input->GetModelDimension();
  std::vector<double> fixed(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c)
  {
    fixed[c] = input->GetFixedValue(c);
  }
  std::vector<std::string> problems;
  const auto requests = this->Requests(fixed, input->GetDimension(), problems);
  frep::LoadedModel projected;
  if (problems.empty())
  {
    std::vector<frep::project::CoordinateRange> axes;
    for (const auto& [c, range] : requests)
    {
      axes.push_back({ c + 1, range[0], range[1] });
    }
    frep::project::ProjectionOptions options;
    options.tolerance = this->Tolerance;
    options.band = this->Band;
    options.parameters = input->GetParameters();
    options.keep_coordinates = true;
    projected = frep::project::project(input->GetModel(), axes, options);
    if (!projected.ok())
    {
      problems.push_back(projected.message());
    }
  }
  if (!problems.empty())
  {
    std::ostringstream message;
    message << "cannot project " << input->GetObjectName() << " (the output is empty):";
    for (const std::string& p : problems)
    {
      message << "\n  " << p;
    }
    vtkErrorMacro(<< message.str());
    return 1;
  }

  // The projected model keeps the input's coordinates: copy their names, intervals, what the
  // input fixed and its order of the free ones; the projected coordinates are fixed (unread).
  output->SetModel(projected.model);
  std::vector<int> free;
  for (int c = 0; c < n; ++c)
  {
    output->SetCoordinateName(c, input->GetCoordinateName(c));
    double range[2];
    input->GetCoordinateRange(c, range);
    output->SetCoordinateRange(c, range[0], range[1]);
    if (input->IsCoordinateFixed(c))
    {
      output->FixCoordinate(c, input->GetFixedValue(c));
    }
  }
  for (const auto& [c, range] : requests)
  {
    output->FixCoordinate(c, range[0]);
  }
  for (const int c : input->GetFreeCoordinates())
  {
    if (requests.count(c) == 0)
    {
      free.push_back(c);
    }
  }
  output->SetFreeCoordinates(free);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepProjection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ProjectedCoordinate: " << this->ProjectedCoordinate << "\n";
  os << indent << "ProjectedRange: " << this->ProjectedRange[0] << " " << this->ProjectedRange[1]
     << "\n";
  os << indent << "Added:";
  for (const auto& [c, range] : this->Added)
  {
    os << " [" << c << "]=" << range[0] << ":" << range[1];
  }
  os << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "Band: " << this->Band << "\n";
}
