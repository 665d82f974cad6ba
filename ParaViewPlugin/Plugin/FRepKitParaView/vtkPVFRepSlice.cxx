#include "vtkPVFRepSlice.h"

#include "vtkFRepObject.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkPVFRepSlice);

namespace
{
std::string Trim(const std::string& s)
{
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos)
  {
    return "";
  }
  const auto end = s.find_last_not_of(" \t");
  return s.substr(begin, end - begin + 1);
}
} // namespace

//------------------------------------------------------------------------------
vtkPVFRepSlice::vtkPVFRepSlice() = default;

//------------------------------------------------------------------------------
vtkPVFRepSlice::~vtkPVFRepSlice() = default;

//------------------------------------------------------------------------------
double vtkPVFRepSlice::GetValue(int coordinate) const
{
  const double values[NumberOfValues] = { this->X1, this->X2, this->X3, this->X4, this->X5,
    this->X6, this->X7, this->X8 };
  return coordinate >= 0 && coordinate < NumberOfValues
    ? values[coordinate]
    : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
std::map<int, double> vtkPVFRepSlice::AutomaticValues(
  const vtkFRepInformation::Metadata& input) const
{
  // The coordinates that stay free: FreeCoordinateOrder's names, else the first
  // OutputDimension free ones not requested through vtkFRepSlice's API.
  std::set<int> explicitly;
  for (const auto& entry : this->FixedValues)
  {
    explicitly.insert(entry.first);
  }
  for (const auto& entry : this->FixedValuesByName)
  {
    for (int i = 0; i < input.GetModelDimension(); ++i)
    {
      if (input.Names[i] == entry.first)
      {
        explicitly.insert(i);
      }
    }
  }
  std::set<int> kept;
  const std::string order = this->FreeCoordinateOrder ? this->FreeCoordinateOrder : "";
  if (!Trim(order).empty())
  {
    std::istringstream names(order);
    std::string name;
    while (std::getline(names, name, ','))
    {
      name = Trim(name);
      for (int i = 0; i < input.GetModelDimension(); ++i)
      {
        if (input.Names[i] == name)
        {
          kept.insert(i);
        }
      }
    }
  }
  else
  {
    for (int c : input.FreeCoordinates)
    {
      if (static_cast<int>(kept.size()) < this->OutputDimension && !explicitly.count(c))
      {
        kept.insert(c);
      }
    }
  }

  // Every other free coordinate: Xi, or the midpoint of its interval beyond x8.
  std::map<int, double> values;
  for (int c : input.FreeCoordinates)
  {
    if (kept.count(c) || explicitly.count(c))
    {
      continue;
    }
    values[c] = c < NumberOfValues ? this->GetValue(c)
                                   : 0.5 * (input.Ranges[c][0] + input.Ranges[c][1]);
  }
  return values;
}

//------------------------------------------------------------------------------
int vtkPVFRepSlice::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The sliders' ranges are the input's intervals, from its metadata keys (nothing upstream is
  // executed); the output's keys are vtkFRepSlice's with the automatic values applied.
  for (auto& range : this->Ranges)
  {
    range[0] = range[1] = 0.0;
  }
  std::fill(std::begin(this->Sliders), std::end(this->Sliders), 0);
  vtkFRepInformation::Metadata input;
  if (!vtkFRepInformation::Get(inputVector[0]->GetInformationObject(0), input))
  {
    return this->Superclass::RequestInformation(request, inputVector, outputVector);
  }
  for (int i = 0; i < NumberOfValues && i < input.GetModelDimension(); ++i)
  {
    this->Ranges[i][0] = input.Ranges[i][0];
    this->Ranges[i][1] = input.Ranges[i][1];
  }
  for (int c : input.FreeCoordinates)
  {
    if (c >= 0 && c < NumberOfValues)
    {
      this->Sliders[c] = 1;
    }
  }
  return this->WithAutomaticValues(input,
    [&] { return this->Superclass::RequestInformation(request, inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkPVFRepSlice::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkFRepInformation::Metadata input;
  if (!vtkFRepInformation::Describe(vtkFRepObject::GetData(inputVector[0]), input))
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  return this->WithAutomaticValues(input,
    [&] { return this->Superclass::RequestData(request, inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkPVFRepSlice::WithAutomaticValues(
  const vtkFRepInformation::Metadata& input, const std::function<int()>& pass)
{
  // Fix the others (without Modified(): this is execution, not a new request), run the
  // superclass, and give the explicit requests back.
  const std::map<int, double> requests = this->FixedValues;
  for (const auto& [c, value] : this->AutomaticValues(input))
  {
    this->FixedValues[c] = value;
  }
  const int result = pass();
  this->FixedValues = requests;
  return result;
}

//------------------------------------------------------------------------------
void vtkPVFRepSlice::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (int i = 0; i < NumberOfValues; ++i)
  {
    os << indent << "X" << i + 1 << ": " << this->GetValue(i) << " (range " << this->Ranges[i][0]
       << ", " << this->Ranges[i][1] << (this->Sliders[i] ? ", slider" : ", no slider") << ")\n";
  }
  os << indent << "OutputDimension: " << this->OutputDimension << "\n";
}
