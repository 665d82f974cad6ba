#include "vtkFRepInformation.h"

#include "vtkDemandDrivenPipeline.h"
#include "vtkExecutive.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationExecutivePortKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationIntegerVectorKey.h"
#include "vtkInformationStringKey.h"
#include "vtkInformationStringVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkFRepInformation);

namespace
{
// A key that copies itself from the first input to every output in REQUEST_INFORMATION, as
// VTK's meta-data keys do (vtkInformationDataObjectMetaDataKey): the executive gives every key
// of the input information that chance (vtkExecutive::CopyDefaultInformation).
template <class Base>
class MetaDataKey : public Base
{
public:
  MetaDataKey(const char* name, const char* location)
    : Base(name, location)
  {
  }
  void CopyDefaultInformation(
    vtkInformation* request, vtkInformation* fromInfo, vtkInformation* toInfo) override
  {
    if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
    {
      this->ShallowCopy(fromInfo, toInfo);
    }
  }
};
}

#define FREPKIT_INFORMATION_KEY(NAME, type)                                                        \
  static vtkInformation##type##Key* vtkFRepInformation_##NAME =                                    \
    new MetaDataKey<vtkInformation##type##Key>(#NAME, "vtkFRepInformation");                       \
  vtkInformation##type##Key* vtkFRepInformation::NAME() { return vtkFRepInformation_##NAME; }

FREPKIT_INFORMATION_KEY(DIMENSION, Integer)
FREPKIT_INFORMATION_KEY(MODEL_DIMENSION, Integer)
FREPKIT_INFORMATION_KEY(OBJECT_NAME, String)
FREPKIT_INFORMATION_KEY(COORDINATE_NAMES, StringVector)
FREPKIT_INFORMATION_KEY(COORDINATE_RANGES, DoubleVector)
FREPKIT_INFORMATION_KEY(FIXED_VALUES, DoubleVector)
FREPKIT_INFORMATION_KEY(FREE_COORDINATES, IntegerVector)
FREPKIT_INFORMATION_KEY(PARAMETERS, DoubleVector)

#undef FREPKIT_INFORMATION_KEY

//------------------------------------------------------------------------------
bool vtkFRepInformation::Metadata::IsCoordinateFixed(int coordinate) const
{
  return coordinate >= 0 && coordinate < static_cast<int>(this->FixedValues.size()) &&
    !std::isnan(this->FixedValues[coordinate]);
}

//------------------------------------------------------------------------------
std::string vtkFRepInformation::Metadata::GetCoordinateName(int coordinate) const
{
  return coordinate >= 0 && coordinate < this->GetModelDimension() ? this->Names[coordinate]
                                                                   : std::string();
}

//------------------------------------------------------------------------------
bool vtkFRepInformation::Has(vtkInformation* info)
{
  return info && info->Has(DIMENSION());
}

//------------------------------------------------------------------------------
void vtkFRepInformation::Remove(vtkInformation* info)
{
  if (!info)
  {
    return;
  }
  info->Remove(DIMENSION());
  info->Remove(MODEL_DIMENSION());
  info->Remove(OBJECT_NAME());
  info->Remove(COORDINATE_NAMES());
  info->Remove(COORDINATE_RANGES());
  info->Remove(FIXED_VALUES());
  info->Remove(FREE_COORDINATES());
  info->Remove(PARAMETERS());
}

//------------------------------------------------------------------------------
bool vtkFRepInformation::Get(vtkInformation* info, Metadata& metadata)
{
  metadata = Metadata();
  if (!Has(info) || !info->Has(MODEL_DIMENSION()))
  {
    return false;
  }
  const int k = info->Get(DIMENSION());
  const int n = info->Get(MODEL_DIMENSION());
  // Empty vectors are absent keys (VTK's vector keys store no empty value).
  const auto length = [info](auto* key) { return info->Has(key) ? key->Length(info) : 0; };
  if (k < 0 || n < k || length(COORDINATE_NAMES()) != n || length(COORDINATE_RANGES()) != 2 * n ||
    length(FIXED_VALUES()) != n || length(FREE_COORDINATES()) != k)
  {
    return false;
  }
  metadata.ObjectName = info->Has(OBJECT_NAME()) ? info->Get(OBJECT_NAME()) : "";
  const double* ranges = n ? info->Get(COORDINATE_RANGES()) : nullptr;
  const double* fixed = n ? info->Get(FIXED_VALUES()) : nullptr;
  for (int c = 0; c < n; ++c)
  {
    const char* name = COORDINATE_NAMES()->Get(info, c);
    metadata.Names.emplace_back(name ? name : "");
    metadata.Ranges.push_back({ ranges[2 * c], ranges[2 * c + 1] });
    metadata.FixedValues.push_back(fixed[c]);
  }
  if (k > 0)
  {
    const int* axes = info->Get(FREE_COORDINATES());
    metadata.FreeCoordinates.assign(axes, axes + k);
  }
  if (const int p = length(PARAMETERS()))
  {
    const double* a = info->Get(PARAMETERS());
    metadata.Parameters.assign(a, a + p);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepInformation::Set(vtkInformation* info, const Metadata& metadata)
{
  if (!info)
  {
    return;
  }
  Remove(info);
  const int n = metadata.GetModelDimension();
  info->Set(DIMENSION(), metadata.GetDimension());
  info->Set(MODEL_DIMENSION(), n);
  info->Set(OBJECT_NAME(), metadata.ObjectName.c_str());
  std::vector<double> ranges;
  std::vector<double> fixed;
  for (int c = 0; c < n; ++c)
  {
    COORDINATE_NAMES()->Append(info, metadata.Names[c]);
    const auto range = c < static_cast<int>(metadata.Ranges.size())
      ? metadata.Ranges[c]
      : std::array<double, 2>{ -10.0, 10.0 };
    ranges.push_back(range[0]);
    ranges.push_back(range[1]);
    fixed.push_back(c < static_cast<int>(metadata.FixedValues.size())
        ? metadata.FixedValues[c]
        : std::numeric_limits<double>::quiet_NaN());
  }
  if (n > 0)
  {
    info->Set(COORDINATE_RANGES(), ranges.data(), 2 * n);
    info->Set(FIXED_VALUES(), fixed.data(), n);
  }
  if (metadata.GetDimension() > 0)
  {
    info->Set(FREE_COORDINATES(), metadata.FreeCoordinates.data(), metadata.GetDimension());
  }
  if (!metadata.Parameters.empty())
  {
    info->Set(PARAMETERS(), metadata.Parameters.data(),
      static_cast<int>(metadata.Parameters.size()));
  }
}

//------------------------------------------------------------------------------
bool vtkFRepInformation::Describe(vtkFRepObject* object, Metadata& metadata)
{
  metadata = Metadata();
  if (!object || !object->HasModel())
  {
    return false;
  }
  metadata.ObjectName = object->GetObjectName();
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    metadata.Names.push_back(object->GetCoordinateName(c));
    std::array<double, 2> range;
    object->GetCoordinateRange(c, range.data());
    metadata.Ranges.push_back(range);
    metadata.FixedValues.push_back(object->GetFixedValue(c));
  }
  metadata.FreeCoordinates = object->GetFreeCoordinates();
  metadata.Parameters = object->GetParameters();
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepInformation::SetFromObject(vtkInformation* info, vtkFRepObject* object)
{
  Metadata metadata;
  if (Describe(object, metadata))
  {
    Set(info, metadata);
  }
  else
  {
    Remove(info);
  }
}

//------------------------------------------------------------------------------
bool vtkFRepInformation::CompleteInputInformation(vtkInformation* inInfo)
{
  if (!inInfo || Has(inInfo))
  {
    return Has(inInfo);
  }
  vtkExecutive* producer = nullptr;
  int port = 0;
  vtkExecutive::PRODUCER()->Get(inInfo, producer, port);
  if (producer && vtkTrivialProducer::SafeDownCast(producer->GetAlgorithm()))
  {
    SetFromObject(inInfo, vtkFRepObject::GetData(inInfo));
  }
  return Has(inInfo);
}

//------------------------------------------------------------------------------
void vtkFRepInformation::RequestWholeObject(vtkInformation* inInfo)
{
  if (!inInfo)
  {
    return;
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

//------------------------------------------------------------------------------
void vtkFRepInformation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
