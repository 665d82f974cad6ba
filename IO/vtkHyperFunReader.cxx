#include "vtkHyperFunReader.h"

#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include "Language/ast.h"

vtkStandardNewMacro(vtkHyperFunReader);

//------------------------------------------------------------------------------
vtkHyperFunReader::vtkHyperFunReader()
{
  this->SetNumberOfOutputPorts(2);
  this->ObjectNames = vtkStringArray::New();
  this->ObjectNames->SetName("ObjectNames");
}

//------------------------------------------------------------------------------
vtkHyperFunReader::~vtkHyperFunReader()
{
  this->ObjectNames->Delete();
}

//------------------------------------------------------------------------------
vtkStringArray* vtkHyperFunReader::GetObjectNames()
{
  return this->ObjectNames;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkHyperFunReader::GetGeometryOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkHyperFunReader::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkHyperFunReader::RequestDataObject(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestDataObject(request, inInfo, outInfo))
  {
    return 0;
  }
  vtkInformation* info = outInfo->GetInformationObject(1);
  if (!vtkPolyData::GetData(info))
  {
    vtkNew<vtkPolyData> geometry;
    info->Set(vtkDataObject::DATA_OBJECT(), geometry);
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHyperFunReader::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_NOT_GENERATED()))
  {
    // A request for the object (port 0) in a parallel run, whose consumers of port 1 ask for
    // their own piece of the mesh (piece r of N on rank r): meshing it now would mesh the whole
    // of it on every rank, then the piece.
    const bool objectOnly = request->Has(vtkExecutive::FROM_OUTPUT_PORT()) &&
      request->Get(vtkExecutive::FROM_OUTPUT_PORT()) == 0;
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    const bool parallel = controller && controller->GetNumberOfProcesses() > 1;
    if (objectOnly && parallel)
    {
      outInfo->GetInformationObject(1)->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
    }
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

//------------------------------------------------------------------------------
int vtkHyperFunReader::RequestInformation(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestInformation(request, inInfo, outInfo))
  {
    return 0;
  }
  // Port 1 is split into slabs by the polygoniser; port 0 is whole on every piece (both ports
  // have CAN_HANDLE_PIECE_REQUEST, see vtkFRepObjectAlgorithm).

  // The object names, from the program the superclass has just parsed (once).
  this->ObjectNames->Initialize();
  const std::shared_ptr<const frep::ast::Program> parsed = this->GetProgram();
  if (!parsed || parsed->objects.empty())
  {
    return 1;
  }
  const frep::ast::Program& program = *parsed;
  const int first = frep::ast::select_default_object(program);
  if (first >= 0)
  {
    this->ObjectNames->InsertNextValue(program.objects[first].name);
  }
  for (int i = 0; i < static_cast<int>(program.objects.size()); ++i)
  {
    if (i != first)
    {
      this->ObjectNames->InsertNextValue(program.objects[i].name);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkHyperFunReader::RequestData(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestData(request, inInfo, outInfo))
  {
    return 0;
  }
  vtkInformation* geometryInfo = outInfo->GetInformationObject(1);
  if (geometryInfo->Get(vtkDemandDrivenPipeline::DATA_NOT_GENERATED()))
  {
    return 1; // port 1 is left as it is (ProcessRequest)
  }
  vtkPolyData* geometry = vtkPolyData::GetData(geometryInfo);
  vtkFRepObject* object = vtkFRepObject::GetData(outInfo, 0);
  if (!geometry)
  {
    vtkErrorMacro(<< "output port 1 is not a vtkPolyData");
    return 0;
  }
  geometry->Initialize();
  if (!this->GenerateGeometry || !object || !object->HasModel() || object->GetDimension() < 2)
  {
    return 1; // nothing to mesh (an error, if any, is reported already)
  }

  // The default cross-section: x1, x2, x3 free, every further coordinate at its midpoint.
  vtkNew<vtkFRepObject> section;
  section->ShallowCopy(object);
  for (int i = 3; i < section->GetModelDimension(); ++i)
  {
    double range[2];
    section->GetCoordinateRange(i, range);
    section->FixCoordinate(i, 0.5 * (range[0] + range[1]));
  }

  vtkNew<vtkFRepPolygonizer> polygonizer;
  polygonizer->SetInputData(section);
  // The default mesh is the long part of this reader: its progress is ours, and our abort
  // (AbortExecute, or an observer asking for it) stops it.
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback(
    [](vtkObject* caller, unsigned long, void* self, void* data)
    {
      auto* reader = static_cast<vtkHyperFunReader*>(self);
      reader->UpdateProgress(*static_cast<double*>(data));
      if (reader->CheckAbort())
      {
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
      }
    });
  polygonizer->AddObserver(vtkCommand::ProgressEvent, forward);
  polygonizer->SetSampleDimensions(
    this->GeometryResolution, this->GeometryResolution, this->GeometryResolution);
  const int piece = geometryInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      ? geometryInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      : 0;
  const int pieces =
    geometryInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
      ? geometryInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
      : 1;
  polygonizer->UpdatePiece(piece, pieces, 0);
  geometry->ShallowCopy(polygonizer->GetOutput());
  geometry->GetFieldData()->ShallowCopy(section->GetFieldData());
  return 1;
}

//------------------------------------------------------------------------------
void vtkHyperFunReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerateGeometry: " << (this->GenerateGeometry ? "On" : "Off") << "\n";
  os << indent << "GeometryResolution: " << this->GeometryResolution << "\n";
  os << indent << "ObjectNames: " << this->ObjectNames->GetNumberOfValues() << " names\n";
}
