#include "vtkFRepSlice.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkFRepSlice);

namespace
{
using Metadata = vtkFRepInformation::Metadata;

// "x1 (coordinate 0)": how a coordinate is named in messages.
std::string Describe(const Metadata* object, int coordinate)
{
  return object->GetCoordinateName(coordinate) + " (coordinate " + std::to_string(coordinate) +
    ")";
}

std::string AllNames(const Metadata* object)
{
  std::string names;
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    names += (c ? ", " : "") + object->GetCoordinateName(c);
  }
  return names;
}

// The model coordinate called `name`, or -1 (with a problem reported) when no coordinate or
// several have that name.
int FindByName(const Metadata* object, const std::string& name, std::vector<std::string>& problems)
{
  int found = -1;
  int matches = 0;
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    if (object->GetCoordinateName(c) == name)
    {
      found = matches++ == 0 ? c : found;
    }
  }
  if (matches == 1)
  {
    return found;
  }
  problems.push_back(matches == 0 ? "no coordinate is called '" + name + "' (the coordinates are " +
        AllNames(object) + ")"
                                  : std::to_string(matches) + " coordinates are called '" +
        name + "'; fix them by index instead");
  return -1;
}

std::string Trim(const std::string& s)
{
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos)
  {
    return std::string();
  }
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}
}

//------------------------------------------------------------------------------
vtkFRepSlice::vtkFRepSlice()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepSlice::~vtkFRepSlice()
{
  this->SetFreeCoordinateOrder(nullptr);
}

//------------------------------------------------------------------------------
void vtkFRepSlice::SetFixedValue(int coordinate, double value)
{
  if (std::isnan(value))
  {
    this->ReleaseCoordinate(coordinate);
    return;
  }
  auto it = this->FixedValues.find(coordinate);
  if (it != this->FixedValues.end() && it->second == value)
  {
    return;
  }
  this->FixedValues[coordinate] = value;
  this->Modified();
}

//------------------------------------------------------------------------------
double vtkFRepSlice::GetFixedValue(int coordinate) const
{
  auto it = this->FixedValues.find(coordinate);
  return it != this->FixedValues.end() ? it->second : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
bool vtkFRepSlice::IsCoordinateFixed(int coordinate) const
{
  return this->FixedValues.count(coordinate) != 0;
}

//------------------------------------------------------------------------------
void vtkFRepSlice::ReleaseCoordinate(int coordinate)
{
  if (this->FixedValues.erase(coordinate) != 0)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkFRepSlice::SetFixedValueByName(const char* name, double value)
{
  const std::string key = name ? name : "";
  if (std::isnan(value))
  {
    this->ReleaseCoordinateByName(name);
    return;
  }
  auto it = this->FixedValuesByName.find(key);
  if (it != this->FixedValuesByName.end() && it->second == value)
  {
    return;
  }
  this->FixedValuesByName[key] = value;
  this->Modified();
}

//------------------------------------------------------------------------------
double vtkFRepSlice::GetFixedValueByName(const char* name) const
{
  auto it = this->FixedValuesByName.find(name ? name : "");
  return it != this->FixedValuesByName.end() ? it->second
                                              : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
void vtkFRepSlice::ReleaseCoordinateByName(const char* name)
{
  if (this->FixedValuesByName.erase(name ? name : "") != 0)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkFRepSlice::ReleaseAllCoordinates()
{
  if (this->FixedValues.empty() && this->FixedValuesByName.empty())
  {
    return;
  }
  this->FixedValues.clear();
  this->FixedValuesByName.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkFRepSlice::GetNumberOfFixedValues() const
{
  return static_cast<int>(this->FixedValues.size() + this->FixedValuesByName.size());
}

//------------------------------------------------------------------------------
int vtkFRepSlice::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  // The output's metadata is the input's with the requests applied: fixed coordinates leave
  // the free ones, the order is FreeCoordinateOrder's. Nothing upstream is executed.
  Metadata metadata;
  if (!vtkFRepInformation::Get(inInfo[0]->GetInformationObject(0), metadata))
  {
    return 1; // an empty input: an empty output, quietly
  }
  std::map<int, double> fixed;
  std::vector<int> order;
  if (!this->Resolve(metadata, fixed, order).empty())
  {
    return 1; // no object: RequestData reports the problems, once
  }
  vtkFRepInformation::Set(outInfo->GetInformationObject(0), Apply(metadata, fixed, order));
  return 1;
}

//------------------------------------------------------------------------------
vtkFRepInformation::Metadata vtkFRepSlice::Apply(
  const Metadata& input, const std::map<int, double>& fixed, const std::vector<int>& order)
{
  Metadata output = input;
  for (const auto& [c, value] : fixed)
  {
    output.FixedValues[c] = value;
  }
  if (!order.empty())
  {
    output.FreeCoordinates = order;
  }
  else
  {
    output.FreeCoordinates.clear();
    for (int c : input.FreeCoordinates)
    {
      if (fixed.count(c) == 0)
      {
        output.FreeCoordinates.push_back(c);
      }
    }
  }
  return output;
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkFRepSlice::Resolve(const Metadata& metadata,
  std::map<int, double>& fixed,
  std::vector<int>& order) const
{
  const Metadata* input = &metadata;
  std::vector<std::string> problems;
  const int n = input->GetModelDimension();

  // Fixing requests: by index, then by name; both end up as model coordinates.
  const auto request = [&](int c, double value, const std::string& how)
  {
    if (!std::isfinite(value))
    {
      problems.push_back("the value " + std::to_string(value) + " for " + Describe(input, c) +
        " is not finite");
      return;
    }
    if (input->IsCoordinateFixed(c))
    {
      std::ostringstream s;
      s << Describe(input, c) << " is already fixed by the input (to " << input->FixedValues[c]
        << "); only free coordinates can be fixed";
      problems.push_back(s.str());
      return;
    }
    auto [it, inserted] = fixed.emplace(c, value);
    if (!inserted && it->second != value)
    {
      std::ostringstream s;
      s << Describe(input, c) << " is fixed twice, to " << it->second << " and (" << how << ") to "
        << value;
      problems.push_back(s.str());
    }
  };
  for (const auto& [c, value] : this->FixedValues)
  {
    if (c < 0 || c >= n)
    {
      problems.push_back("SetFixedValue: coordinate " + std::to_string(c) + " does not exist; " +
        input->ObjectName + " has " + std::to_string(n) + " coordinates, 0.." +
        std::to_string(n - 1) + " (" + AllNames(input) + ")");
      continue;
    }
    request(c, value, "by index");
  }
  for (const auto& [name, value] : this->FixedValuesByName)
  {
    const int c = FindByName(input, name, problems);
    if (c >= 0)
    {
      request(c, value, "by name");
    }
  }

  // The order of the free coordinates, by name.
  const std::string text = this->FreeCoordinateOrder ? this->FreeCoordinateOrder : "";
  if (Trim(text).empty())
  {
    return problems;
  }
  std::vector<bool> listed(n, false);
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    const std::string name = Trim(item);
    if (name.empty())
    {
      problems.push_back("FreeCoordinateOrder '" + text + "' has an empty name");
      continue;
    }
    const int c = FindByName(input, name, problems);
    if (c < 0)
    {
      continue;
    }
    if (listed[c])
    {
      problems.push_back("FreeCoordinateOrder names " + Describe(input, c) + " twice");
      continue;
    }
    listed[c] = true;
    if (fixed.count(c) != 0 || input->IsCoordinateFixed(c))
    {
      std::ostringstream s;
      s << "FreeCoordinateOrder names " << Describe(input, c) << ", which is fixed (to "
        << (fixed.count(c) ? fixed[c] : input->FixedValues[c])
        << (fixed.count(c) ? ")" : " by the input)");
      problems.push_back(s.str());
      continue;
    }
    order.push_back(c);
  }
  if (Trim(text).back() == ',') // getline yields no empty last item
  {
    problems.push_back("FreeCoordinateOrder '" + text + "' has an empty name");
  }
  for (int c = 0; c < n; ++c)
  {
    if (!listed[c] && fixed.count(c) == 0 && !input->IsCoordinateFixed(c))
    {
      problems.push_back(Describe(input, c) +
        " is neither fixed nor named in FreeCoordinateOrder '" + text + "'");
    }
  }
  return problems;
}

//------------------------------------------------------------------------------
int vtkFRepSlice::RequestData(vtkInformation*,
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
    // The producer has reported why (e.g. a parse error); an empty object flows on quietly.
    vtkDebugMacro(<< "empty input: empty output");
    return 1;
  }

  Metadata metadata;
  vtkFRepInformation::Describe(input, metadata);
  std::map<int, double> fixed;
  std::vector<int> order;
  const std::vector<std::string> problems = this->Resolve(metadata, fixed, order);
  if (!problems.empty())
  {
    std::ostringstream message;
    message << "cannot slice " << input->GetObjectName() << " (the output is empty):";
    for (const std::string& p : problems)
    {
      message << "\n  " << p;
    }
    vtkErrorMacro(<< message.str());
    return 1; // the output stays empty; no second "returned failure" error
  }

  output->ShallowCopy(input);
  for (const auto& [c, value] : fixed)
  {
    output->FixCoordinate(c, value);
  }
  if (!order.empty() && !output->SetFreeCoordinates(order))
  {
    // Resolve() checked what SetFreeCoordinates checks; reaching this is a bug.
    output->Initialize();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepSlice::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FixedValues:";
  for (const auto& [c, value] : this->FixedValues)
  {
    os << " [" << c << "]=" << value;
  }
  os << "\n";
  os << indent << "FixedValuesByName:";
  for (const auto& [name, value] : this->FixedValuesByName)
  {
    os << " '" << name << "'=" << value;
  }
  os << "\n";
  os << indent << "FreeCoordinateOrder: "
     << (this->FreeCoordinateOrder ? this->FreeCoordinateOrder : "(none)") << "\n";
}
