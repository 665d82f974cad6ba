#include "vtkFRepObject.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkFRepObject);

namespace
{
constexpr const char* DimensionArray = "FRepDimension";
constexpr const char* ModelDimensionArray = "FRepModelDimension";
constexpr const char* ObjectNameArray = "FRepObjectName";
constexpr const char* CoordinateNamesArray = "FRepCoordinateNames";
constexpr const char* IntervalsArray = "FRepIntervals";
constexpr const char* FixedValuesArray = "FRepFixedValues";
constexpr const char* ParametersArray = "FRepParameters";
}

//------------------------------------------------------------------------------
vtkFRepObject::vtkFRepObject()
{
  this->UpdateFieldData();
}

//------------------------------------------------------------------------------
vtkFRepObject::~vtkFRepObject() = default;

//------------------------------------------------------------------------------
void vtkFRepObject::Initialize()
{
  this->Superclass::Initialize(); // clears the field data
  this->Model.reset();
  this->Coordinates.clear();
  this->FreeCoordinates.clear();
  this->Parameters.clear();
  this->StateChanged();
}

//------------------------------------------------------------------------------
void vtkFRepObject::SetModel(std::shared_ptr<const frep::Model> model)
{
  this->Model = std::move(model);
  this->Coordinates.clear();
  this->FreeCoordinates.clear();
  this->Parameters.clear();
  const int n = this->Model ? this->Model->x_dim() : 0;
  for (int i = 0; i < n; ++i)
  {
    Coordinate c;
    c.Name = "x" + std::to_string(i + 1);
    this->Coordinates.push_back(c);
    this->FreeCoordinates.push_back(i);
  }
  this->StateChanged();
}

//------------------------------------------------------------------------------
std::string vtkFRepObject::GetObjectName() const
{
  return this->Model ? this->Model->name() : std::string();
}

//------------------------------------------------------------------------------
int vtkFRepObject::GetFreeCoordinate(int axis) const
{
  if (axis < 0 || axis >= this->GetDimension())
  {
    return -1;
  }
  return this->FreeCoordinates[axis];
}

//------------------------------------------------------------------------------
bool vtkFRepObject::CheckCoordinate(int coordinate, const char* method) const
{
  if (coordinate < 0 || coordinate >= this->GetModelDimension())
  {
    vtkErrorMacro(<< method << ": coordinate " << coordinate << " out of range [0, "
                  << this->GetModelDimension() << ")");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepObject::SetCoordinateName(int coordinate, const std::string& name)
{
  if (!this->CheckCoordinate(coordinate, "SetCoordinateName") ||
      this->Coordinates[coordinate].Name == name)
  {
    return;
  }
  this->Coordinates[coordinate].Name = name;
  this->StateChanged();
}

//------------------------------------------------------------------------------
std::string vtkFRepObject::GetCoordinateName(int coordinate) const
{
  if (!this->CheckCoordinate(coordinate, "GetCoordinateName"))
  {
    return std::string();
  }
  return this->Coordinates[coordinate].Name;
}

//------------------------------------------------------------------------------
void vtkFRepObject::SetCoordinateRange(int coordinate, double lo, double hi)
{
  if (!this->CheckCoordinate(coordinate, "SetCoordinateRange"))
  {
    return;
  }
  if (!(lo <= hi)) // also refuses NaN
  {
    vtkErrorMacro(<< "SetCoordinateRange: empty interval [" << lo << ", " << hi
                  << "] for coordinate " << coordinate);
    return;
  }
  Coordinate& c = this->Coordinates[coordinate];
  if (c.Range[0] == lo && c.Range[1] == hi)
  {
    return;
  }
  c.Range[0] = lo;
  c.Range[1] = hi;
  this->StateChanged();
}

//------------------------------------------------------------------------------
void vtkFRepObject::GetCoordinateRange(int coordinate, double range[2]) const
{
  if (!this->CheckCoordinate(coordinate, "GetCoordinateRange"))
  {
    range[0] = range[1] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  range[0] = this->Coordinates[coordinate].Range[0];
  range[1] = this->Coordinates[coordinate].Range[1];
}

//------------------------------------------------------------------------------
void vtkFRepObject::FixCoordinate(int coordinate, double value)
{
  if (!this->CheckCoordinate(coordinate, "FixCoordinate"))
  {
    return;
  }
  Coordinate& c = this->Coordinates[coordinate];
  if (c.Fixed && c.Value == value)
  {
    return;
  }
  c.Fixed = true;
  c.Value = value;
  auto& free = this->FreeCoordinates;
  free.erase(std::remove(free.begin(), free.end(), coordinate), free.end());
  this->StateChanged();
}

//------------------------------------------------------------------------------
void vtkFRepObject::ReleaseCoordinate(int coordinate)
{
  if (!this->CheckCoordinate(coordinate, "ReleaseCoordinate") ||
      !this->Coordinates[coordinate].Fixed)
  {
    return;
  }
  this->Coordinates[coordinate].Fixed = false;
  this->FreeCoordinates.push_back(coordinate);
  this->StateChanged();
}

//------------------------------------------------------------------------------
bool vtkFRepObject::IsCoordinateFixed(int coordinate) const
{
  return coordinate >= 0 && coordinate < this->GetModelDimension() &&
         this->Coordinates[coordinate].Fixed;
}

//------------------------------------------------------------------------------
double vtkFRepObject::GetFixedValue(int coordinate) const
{
  return this->IsCoordinateFixed(coordinate) ? this->Coordinates[coordinate].Value
                                             : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
bool vtkFRepObject::SetFreeCoordinates(const std::vector<int>& coordinates)
{
  const int n = this->GetModelDimension();
  std::vector<bool> listed(n, false);
  for (int c : coordinates)
  {
    if (c < 0 || c >= n)
    {
      vtkErrorMacro(<< "SetFreeCoordinates: coordinate " << c << " out of range [0, " << n << ")");
      return false;
    }
    if (listed[c])
    {
      vtkErrorMacro(<< "SetFreeCoordinates: coordinate " << c << " (" << this->Coordinates[c].Name
                    << ") listed twice");
      return false;
    }
    listed[c] = true;
  }
  for (int c = 0; c < n; ++c)
  {
    if (!listed[c] && !this->Coordinates[c].Fixed)
    {
      vtkErrorMacro(<< "SetFreeCoordinates: coordinate " << c << " (" << this->Coordinates[c].Name
                    << ") is neither listed as free nor fixed to a value");
      return false;
    }
  }
  for (int c : coordinates)
  {
    this->Coordinates[c].Fixed = false;
  }
  if (this->FreeCoordinates != coordinates)
  {
    this->FreeCoordinates = coordinates;
    this->StateChanged();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepObject::SetParameters(const std::vector<double>& parameters)
{
  if (this->Parameters == parameters)
  {
    return;
  }
  this->Parameters = parameters;
  this->StateChanged();
}

//------------------------------------------------------------------------------
double vtkFRepObject::GetParameter(int i) const
{
  return i >= 0 && i < this->GetNumberOfParameters() ? this->Parameters[i] : 0.0;
}

//------------------------------------------------------------------------------
frep::Specialisation vtkFRepObject::GetSpecialisation() const
{
  frep::Specialisation s;
  s.parameters = this->Parameters;
  if (this->Model)
  {
    // The engine expects exactly a_dim values at most; extra ones are ignored by contract,
    // but keep the description tidy.
    if (static_cast<int>(s.parameters.size()) > this->Model->a_dim())
    {
      s.parameters.resize(this->Model->a_dim());
    }
  }
  s.fixed.resize(this->Coordinates.size());
  for (std::size_t i = 0; i < this->Coordinates.size(); ++i)
  {
    if (this->Coordinates[i].Fixed)
    {
      s.fixed[i] = this->Coordinates[i].Value;
    }
  }
  s.input_order = this->FreeCoordinates;
  return s;
}

//------------------------------------------------------------------------------
std::shared_ptr<const frep::Tape> vtkFRepObject::GetTape() const
{
  std::lock_guard<std::mutex> lock(this->TapeMutex);
  if (!this->CachedTape && this->Model)
  {
    this->CachedTape = this->Model->specialise(this->GetSpecialisation());
  }
  return this->CachedTape;
}

//------------------------------------------------------------------------------
vtkFRepObject::EvaluationDescription vtkFRepObject::GetEvaluationDescription() const
{
  EvaluationDescription d;
  if (!this->Model)
  {
    return d;
  }
  d.Tape = this->GetTape();
  d.Coordinates = this->FreeCoordinates;
  for (int c : this->FreeCoordinates)
  {
    d.Names.push_back(this->Coordinates[c].Name);
    d.Ranges.push_back({ this->Coordinates[c].Range[0], this->Coordinates[c].Range[1] });
  }
  d.AttributeCount = this->Model->s_dim();
  return d;
}

//------------------------------------------------------------------------------
void vtkFRepObject::StateChanged()
{
  {
    std::lock_guard<std::mutex> lock(this->TapeMutex);
    this->CachedTape.reset();
  }
  this->UpdateFieldData();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepObject::UpdateFieldData()
{
  vtkFieldData* fd = this->GetFieldData();
  if (!fd)
  {
    vtkNew<vtkFieldData> created;
    this->SetFieldData(created);
    fd = created;
  }
  // Always new arrays: after a ShallowCopy the old ones are shared with another object.
  for (const char* name : { DimensionArray,
         ModelDimensionArray,
         ObjectNameArray,
         CoordinateNamesArray,
         IntervalsArray,
         FixedValuesArray,
         ParametersArray })
  {
    fd->RemoveArray(name);
  }
  if (!this->Model)
  {
    return;
  }

  vtkNew<vtkIntArray> dimension;
  dimension->SetName(DimensionArray);
  dimension->InsertNextValue(this->GetDimension());
  fd->AddArray(dimension);

  vtkNew<vtkIntArray> modelDimension;
  modelDimension->SetName(ModelDimensionArray);
  modelDimension->InsertNextValue(this->GetModelDimension());
  fd->AddArray(modelDimension);

  vtkNew<vtkStringArray> objectName;
  objectName->SetName(ObjectNameArray);
  objectName->InsertNextValue(this->Model->name());
  fd->AddArray(objectName);

  vtkNew<vtkStringArray> names;
  names->SetName(CoordinateNamesArray);
  vtkNew<vtkDoubleArray> intervals;
  intervals->SetName(IntervalsArray);
  intervals->SetNumberOfComponents(2);
  intervals->SetComponentName(0, "lo");
  intervals->SetComponentName(1, "hi");
  for (int c : this->FreeCoordinates)
  {
    names->InsertNextValue(this->Coordinates[c].Name);
    intervals->InsertNextTuple(this->Coordinates[c].Range);
  }
  fd->AddArray(names);
  fd->AddArray(intervals);

  vtkNew<vtkDoubleArray> fixed;
  fixed->SetName(FixedValuesArray);
  for (int c = 0; c < this->GetModelDimension(); ++c)
  {
    fixed->InsertNextValue(this->GetFixedValue(c));
  }
  fd->AddArray(fixed);

  vtkNew<vtkDoubleArray> parameters;
  parameters->SetName(ParametersArray);
  for (double a : this->Parameters)
  {
    parameters->InsertNextValue(a);
  }
  fd->AddArray(parameters);
}

//------------------------------------------------------------------------------
void vtkFRepObject::CopyState(vtkFRepObject* src)
{
  this->Coordinates = src->Coordinates;
  this->FreeCoordinates = src->FreeCoordinates;
  this->Parameters = src->Parameters;
  this->StateChanged();
}

//------------------------------------------------------------------------------
void vtkFRepObject::ShallowCopy(vtkDataObject* src)
{
  if (src == this)
  {
    return;
  }
  this->Superclass::ShallowCopy(src);
  if (auto* obj = vtkFRepObject::SafeDownCast(src))
  {
    this->Model = obj->Model;
    this->CopyState(obj);
  }
}

//------------------------------------------------------------------------------
void vtkFRepObject::DeepCopy(vtkDataObject* src)
{
  if (src == this)
  {
    return;
  }
  this->Superclass::DeepCopy(src);
  auto* obj = vtkFRepObject::SafeDownCast(src);
  if (!obj)
  {
    return;
  }
  this->Model.reset();
  if (obj->Model && !obj->Model->program())
  {
    // A composed model (frep::combine) has no program to recompile; it is immutable and owns
    // no per-evaluation state, so sharing it is as good as a copy.
    this->Model = obj->Model;
  }
  else if (obj->Model)
  {
    // A model is immutable and owns no per-evaluation state, so a copy is a recompilation of
    // the same (immutable) program: the same code, owned by this object alone.
    frep::Model::CompileResult compiled =
      frep::Model::compile(obj->Model->program(), obj->Model->object_index());
    if (compiled.model)
    {
      this->Model = std::move(compiled.model);
    }
    else
    {
      vtkErrorMacro(<< "DeepCopy: recompiling " << obj->Model->name()
                    << " failed; sharing the source's model instead: "
                    << frep::format_diagnostics(compiled.diagnostics));
      this->Model = obj->Model;
    }
  }
  this->CopyState(obj);
}

//------------------------------------------------------------------------------
unsigned long vtkFRepObject::GetActualMemorySize()
{
  std::size_t bytes = sizeof(*this) + this->Coordinates.size() * sizeof(Coordinate) +
                      this->FreeCoordinates.size() * sizeof(int) +
                      this->Parameters.size() * sizeof(double);
  for (const Coordinate& c : this->Coordinates)
  {
    bytes += c.Name.capacity();
  }
  return this->Superclass::GetActualMemorySize() +
         static_cast<unsigned long>((bytes + 1023) / 1024);
}

//------------------------------------------------------------------------------
vtkFRepObject* vtkFRepObject::GetData(vtkInformation* info)
{
  return info ? vtkFRepObject::SafeDownCast(info->Get(vtkDataObject::DATA_OBJECT())) : nullptr;
}

//------------------------------------------------------------------------------
vtkFRepObject* vtkFRepObject::GetData(vtkInformationVector* v, int i)
{
  return v ? vtkFRepObject::GetData(v->GetInformationObject(i)) : nullptr;
}

//------------------------------------------------------------------------------
void vtkFRepObject::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: ";
  if (this->Model)
  {
    os << this->Model->name() << " (" << this->Model->x_dim() << " coordinates, a["
       << this->Model->a_dim() << "], s[" << this->Model->s_dim() << "], "
       << (this->Model->is_compiled() ? "compiled" : "interpreted") << ", shared by "
       << this->Model.use_count() << ")\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "Dimension: " << this->GetDimension() << "\n";
  os << indent << "ModelDimension: " << this->GetModelDimension() << "\n";
  os << indent << "Coordinates:\n";
  for (int c = 0; c < this->GetModelDimension(); ++c)
  {
    const Coordinate& co = this->Coordinates[c];
    os << indent.GetNextIndent() << c << " " << co.Name << " [" << co.Range[0] << ", "
       << co.Range[1] << "]";
    if (co.Fixed)
    {
      os << " fixed = " << co.Value;
    }
    os << "\n";
  }
  os << indent << "FreeCoordinates:";
  for (int c : this->FreeCoordinates)
  {
    os << " " << c;
  }
  os << "\n";
  os << indent << "Parameters:";
  for (double a : this->Parameters)
  {
    os << " " << a;
  }
  os << "\n";
  std::lock_guard<std::mutex> lock(this->TapeMutex);
  os << indent << "CachedTape: ";
  if (this->CachedTape)
  {
    os << this->CachedTape->code.size() << " instructions, " << this->CachedTape->input_count
       << " inputs\n";
  }
  else
  {
    os << "(none)\n";
  }
}
