#include "vtkPVFRepSlice.h"

#include "vtkFRepObject.h"

#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortKey.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
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
int vtkPVFRepSlice::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The sliders' ranges are the input's intervals: bring the input up to date now (the FRep
  // producers only parse, compile or specialise), with the request RequestData will make.
  for (auto& range : this->Ranges)
  {
    range[0] = range[1] = 0.0;
  }
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo)
  {
    vtkExecutive* producer = nullptr;
    int port = 0;
    vtkExecutive::PRODUCER()->Get(inInfo, producer, port);
    if (auto* pipeline = vtkStreamingDemandDrivenPipeline::SafeDownCast(producer))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      pipeline->Update(port);
    }
    if (vtkFRepObject* input = vtkFRepObject::GetData(inInfo))
    {
      for (int i = 0; i < NumberOfValues && i < input->GetModelDimension(); ++i)
      {
        input->GetCoordinateRange(i, this->Ranges[i]);
      }
    }
  }
  return this->Superclass::RequestInformation(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkPVFRepSlice::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkFRepObject* input = vtkFRepObject::GetData(inputVector[0]);
  if (!input || !input->HasModel())
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }

  // The coordinates that stay free: FreeCoordinateOrder's names, else the first
  // OutputDimension free ones not requested through vtkFRepSlice's API.
  std::set<int> explicitly;
  for (const auto& entry : this->FixedValues)
  {
    explicitly.insert(entry.first);
  }
  for (const auto& entry : this->FixedValuesByName)
  {
    for (int i = 0; i < input->GetModelDimension(); ++i)
    {
      if (input->GetCoordinateName(i) == entry.first)
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
      for (int i = 0; i < input->GetModelDimension(); ++i)
      {
        if (input->GetCoordinateName(i) == name)
        {
          kept.insert(i);
        }
      }
    }
  }
  else
  {
    for (int c : input->GetFreeCoordinates())
    {
      if (static_cast<int>(kept.size()) < this->OutputDimension && !explicitly.count(c))
      {
        kept.insert(c);
      }
    }
  }

  // Fix the others (without Modified(): this is execution, not a new request), run the
  // superclass, and give the explicit requests back.
  const std::map<int, double> requests = this->FixedValues;
  for (int c : input->GetFreeCoordinates())
  {
    if (kept.count(c) || explicitly.count(c))
    {
      continue;
    }
    double value = this->GetValue(c);
    if (c >= NumberOfValues)
    {
      double range[2];
      input->GetCoordinateRange(c, range);
      value = 0.5 * (range[0] + range[1]);
    }
    this->FixedValues[c] = value;
  }
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
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
       << ", " << this->Ranges[i][1] << ")\n";
  }
  os << indent << "OutputDimension: " << this->OutputDimension << "\n";
}
