#include "vtkHyperFunSource.h"

#include "Shapes/tape_function.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "Compiler/load_model.h"
#include "Mesh/coordinate_bounds.h"

#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkHyperFunSource);

//------------------------------------------------------------------------------
vtkHyperFunSource::vtkHyperFunSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkHyperFunSource::~vtkHyperFunSource()
{
  this->SetModelText(nullptr);
  this->SetFileName(nullptr);
  this->SetObjectName(nullptr);
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::SetParameter(int i, double value)
{
  if (i < 0)
  {
    vtkErrorMacro(<< "SetParameter: negative index " << i);
    return;
  }
  if (i < this->GetNumberOfParameters() && this->Parameters[i] == value)
  {
    return;
  }
  if (i >= this->GetNumberOfParameters())
  {
    this->Parameters.resize(i + 1, 0.0);
  }
  this->Parameters[i] = value;
  this->Modified();
}

//------------------------------------------------------------------------------
double vtkHyperFunSource::GetParameter(int i) const
{
  return i >= 0 && i < this->GetNumberOfParameters() ? this->Parameters[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::SetNumberOfParameters(int n)
{
  if (n < 0)
  {
    vtkErrorMacro(<< "SetNumberOfParameters: negative count " << n);
    return;
  }
  if (n == this->GetNumberOfParameters())
  {
    return;
  }
  this->Parameters.resize(n, 0.0);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::SetCoordinateRange(int i, double lo, double hi)
{
  if (i < 0)
  {
    vtkErrorMacro(<< "SetCoordinateRange: negative coordinate " << i);
    return;
  }
  if (!(lo <= hi))
  {
    vtkErrorMacro(<< "SetCoordinateRange: empty interval [" << lo << ", " << hi
                  << "] for coordinate " << i);
    return;
  }
  const std::size_t index = static_cast<std::size_t>(i);
  if (index < this->HasCoordinateRange.size() && this->HasCoordinateRange[index] &&
      this->CoordinateRanges[index][0] == lo && this->CoordinateRanges[index][1] == hi)
  {
    return;
  }
  if (index >= this->HasCoordinateRange.size())
  {
    this->HasCoordinateRange.resize(index + 1, false);
    this->CoordinateRanges.resize(index + 1, { 0.0, 0.0 });
  }
  this->HasCoordinateRange[index] = true;
  this->CoordinateRanges[index] = { lo, hi };
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::GetCoordinateRange(int i, double range[2]) const
{
  const std::size_t index = static_cast<std::size_t>(i);
  if (i >= 0 && index < this->HasCoordinateRange.size() && this->HasCoordinateRange[index])
  {
    range[0] = this->CoordinateRanges[index][0];
    range[1] = this->CoordinateRanges[index][1];
    return;
  }
  // The solid's bounds only while they are those of the source as it is now.
  // (GetMTime is not const in VTK; it only reads.)
  if (i >= 0 && index < this->FoundRanges.size() &&
      this->ModelTime.GetMTime() > const_cast<vtkHyperFunSource*>(this)->GetMTime())
  {
    range[0] = this->FoundRanges[index][0];
    range[1] = this->FoundRanges[index][1];
    return;
  }
  range[0] = this->DefaultCoordinateRange[0];
  range[1] = this->DefaultCoordinateRange[1];
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::RemoveAllCoordinateRanges()
{
  if (this->HasCoordinateRange.empty())
  {
    return;
  }
  this->HasCoordinateRange.clear();
  this->CoordinateRanges.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::AddUserLibrary(const char* path)
{
  this->UserLibraries.emplace_back(path ? path : "");
  this->UserFunctionTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::RemoveAllUserLibraries()
{
  this->UserLibraries.clear();
  this->UserFunctionTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::AddShape(const char* name, vtkFRepObject* object)
{
  if (!name || !object || !object->HasModel())
  {
    vtkErrorMacro(<< "AddShape: a name and an object with a model are needed");
    return;
  }
  std::shared_ptr<const frep::Tape> tape = object->GetTape();
  if (!tape)
  {
    vtkErrorMacro(<< "AddShape: the object '" << name << "' has no tape");
    return;
  }
  this->ShapeNames.emplace_back(name);
  this->ShapeTapes.push_back(std::move(tape));
  this->UserFunctionTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::RemoveAllShapes()
{
  this->ShapeNames.clear();
  this->ShapeTapes.clear();
  this->UserFunctionTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkHyperFunSource::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
  // Parse and compile now (once: RequestData reuses the model) and describe the object, so
  // that downstream filters need not execute this source to learn its coordinates.
  std::shared_ptr<const frep::Model> model = this->UpdateModel();
  if (model)
  {
    vtkNew<vtkFRepObject> described;
    this->FillObject(model, described);
    vtkFRepInformation::SetFromObject(outInfo->GetInformationObject(0), described);
  }
  return 1;
}

//------------------------------------------------------------------------------
std::shared_ptr<const frep::Model> vtkHyperFunSource::UpdateModel()
{
  if (this->ModelTime.GetMTime() > this->GetMTime())
  {
    return this->CachedModel; // built since the last change (null: reported then)
  }
  this->FoundRanges.clear();
  this->BuildModel();
  if (this->CachedModel)
  {
    this->UpdateRanges(*this->CachedModel);
  }
  this->ModelTime.Modified();
  return this->CachedModel;
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::UpdateRanges(const frep::Model& model)
{
  const int n = model.x_dim();
  std::vector<std::optional<frep::Interval>> given(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    double range[2];
    this->GetCoordinateRange(i, range);
    const std::size_t index = static_cast<std::size_t>(i);
    if (!this->UseSolidBounds ||
        (index < this->HasCoordinateRange.size() && this->HasCoordinateRange[index]))
    {
      given[index] = frep::Interval{ range[0], range[1] };
    }
  }
  const frep::Interval fallback{ this->DefaultCoordinateRange[0], this->DefaultCoordinateRange[1] };
  if (!(fallback.lo < fallback.hi))
  {
    return; // FillObject's ranges say it: DefaultCoordinateRange is used as set
  }
  try
  {
    const frep::mesh::CoordinateBounds bounds =
      frep::mesh::find_coordinate_bounds(model, this->Parameters, given, fallback);
    for (const frep::Interval& range : bounds.ranges)
    {
      this->FoundRanges.push_back({ range.lo, range.hi });
    }
    if (bounds.rule == frep::mesh::CoordinateBounds::Rule::None && !bounds.note.empty() &&
        this->WarnedModel.lock() != this->CachedModel)
    {
      this->WarnedModel = this->CachedModel;
      vtkWarningMacro(<< model.name() << ": " << bounds.note
                      << "; the coordinates without a range get DefaultCoordinateRange ["
                      << fallback.lo << ", " << fallback.hi << "] (SetCoordinateRange to choose)");
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< model.name() << ": the solid's bounds: " << e.what());
  }
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::FillObject(const std::shared_ptr<const frep::Model>& model,
  vtkFRepObject* output) const
{
  output->SetModel(model);
  for (int i = 0; i < model->x_dim(); ++i)
  {
    double range[2];
    this->GetCoordinateRange(i, range);
    output->SetCoordinateRange(i, range[0], range[1]);
  }
  output->SetParameters(this->Parameters);
}

//------------------------------------------------------------------------------
bool vtkHyperFunSource::ReadProgramText(std::string& text, std::string& sourceName)
{
  if (this->FileName && *this->FileName)
  {
    std::ifstream in(this->FileName, std::ios::binary);
    if (!in)
    {
      vtkErrorMacro(<< this->FileName << ": cannot open the file");
      return false;
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad())
    {
      vtkErrorMacro(<< this->FileName << ": cannot read the file");
      return false;
    }
    text = buffer.str();
    sourceName = this->FileName;
    return true;
  }
  if (this->ModelText)
  {
    text = this->ModelText;
    sourceName = "<string>";
    return true;
  }
  vtkErrorMacro(<< "neither FileName nor ModelText is set");
  return false;
}

//------------------------------------------------------------------------------
bool vtkHyperFunSource::AddUserFunctions(frep::LoadOptions& options)
{
  options.libraries = this->UserLibraries;
  if (this->ShapeNames.empty())
  {
    return true;
  }
  auto shapes = std::make_shared<frep::UserFunctionRegistry>();
  for (std::size_t i = 0; i < this->ShapeNames.size(); ++i)
  {
    const std::string e =
      shapes->add(frep::shapes::tape_function(this->ShapeNames[i], this->ShapeTapes[i]));
    if (!e.empty())
    {
      vtkErrorMacro(<< "AddShape: " << e);
      return false;
    }
  }
  options.functions = shapes;
  return true;
}

//------------------------------------------------------------------------------
std::shared_ptr<const frep::Model> vtkHyperFunSource::BuildModel()
{
  std::string text;
  std::string sourceName;
  if (!this->ReadProgramText(text, sourceName))
  {
    this->CachedModel.reset();
    this->CachedProgram.reset();
    return nullptr;
  }
  const std::string objectName = this->ObjectName ? this->ObjectName : "";

  if (this->CachedModel && text == this->CachedText && sourceName == this->CachedSourceName &&
      objectName == this->CachedObjectName && this->CachedTime > this->UserFunctionTime)
  {
    return this->CachedModel;
  }
  this->CachedModel.reset();
  this->CachedProgram.reset();

  // The one loading call of every tool (Compiler/load_model.h): .vm tapes by the file name's
  // extension, HyperFun library files and shared libraries, the same messages as frepkit's.
  frep::LoadOptions options;
  options.object = objectName;
  if (!this->AddUserFunctions(options))
  {
    return nullptr;
  }
  frep::LoadedModel loaded =
    frep::load_model(frep::ModelSource::from_text(text, sourceName), options);
  this->CachedProgram = loaded.program;
  if (!loaded.ok())
  {
    for (const frep::Diagnostic& d : loaded.diagnostics)
    {
      vtkErrorMacro(<< d.format());
    }
    return nullptr;
  }
  this->CachedModel = std::move(loaded.model);
  this->CachedText = std::move(text);
  this->CachedSourceName = std::move(sourceName);
  this->CachedObjectName = objectName;
  this->CachedTime.Modified();
  return this->CachedModel;
}

//------------------------------------------------------------------------------
int vtkHyperFunSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
  vtkFRepObject* output = vtkFRepObject::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkFRepObject");
    return 0;
  }
  output->Initialize();

  // Built by RequestInformation (unless the source changed since): no second parse.
  std::shared_ptr<const frep::Model> model = this->UpdateModel();
  if (!model)
  {
    return 1; // the errors are reported; the output stays empty
  }
  this->FillObject(model, output);
  if (model->a_dim() < this->GetNumberOfParameters())
  {
    vtkWarningMacro(<< model->name() << " has a[" << model->a_dim() << "] but "
                    << this->GetNumberOfParameters()
                    << " parameters are set; the extra ones are ignored");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHyperFunSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ModelText: " << (this->ModelText ? this->ModelText : "(none)") << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ObjectName: " << (this->ObjectName ? this->ObjectName : "(none)") << "\n";
  os << indent << "UserLibraries (" << this->UserLibraries.size() << "):";
  for (const std::string& path : this->UserLibraries)
  {
    os << " " << path;
  }
  os << "\n" << indent << "Shapes (" << this->ShapeNames.size() << "):";
  for (const std::string& name : this->ShapeNames)
  {
    os << " " << name;
  }
  os << "\n";
  os << indent << "Parameters (" << this->Parameters.size() << "):";
  for (double a : this->Parameters)
  {
    os << " " << a;
  }
  os << "\n";
  os << indent << "UseSolidBounds: " << (this->UseSolidBounds ? "On" : "Off") << "\n";
  os << indent << "DefaultCoordinateRange: [" << this->DefaultCoordinateRange[0] << ", "
     << this->DefaultCoordinateRange[1] << "]\n";
  os << indent << "CoordinateRanges:";
  for (std::size_t i = 0; i < this->HasCoordinateRange.size(); ++i)
  {
    if (this->HasCoordinateRange[i])
    {
      os << " x" << i + 1 << "=[" << this->CoordinateRanges[i][0] << ", "
         << this->CoordinateRanges[i][1] << "]";
    }
  }
  os << "\n";
  os << indent
     << "CachedModel: " << (this->CachedModel ? this->CachedModel->name() : std::string("(none)"))
     << "\n";
}
