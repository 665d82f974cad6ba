#include "vtkFRepObjectAlgorithm.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstring>

vtkStandardNewMacro(vtkFRepObjectAlgorithm);

//------------------------------------------------------------------------------
vtkFRepObjectAlgorithm::vtkFRepObjectAlgorithm()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepObjectAlgorithm::~vtkFRepObjectAlgorithm() = default;

//------------------------------------------------------------------------------
vtkFRepObject* vtkFRepObjectAlgorithm::GetOutput()
{
  return this->GetOutput(0);
}

//------------------------------------------------------------------------------
vtkFRepObject* vtkFRepObjectAlgorithm::GetOutput(int port)
{
  return vtkFRepObject::SafeDownCast(this->GetOutputDataObject(port));
}

//------------------------------------------------------------------------------
void vtkFRepObjectAlgorithm::SetInputData(vtkDataObject* input)
{
  this->SetInputData(0, input);
}

//------------------------------------------------------------------------------
void vtkFRepObjectAlgorithm::SetInputData(int port, vtkDataObject* input)
{
  this->SetInputDataObject(port, input);
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkFRepObjectAlgorithm::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inInfo, outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    for (int port = 0; port < outInfo->GetNumberOfInformationObjects(); ++port)
    {
      vtkInformation* info = outInfo->GetInformationObject(port);
      // The executive has copied the first input's keys here (CopyDefaultInformation); the
      // subclass decides what this output is. Nothing stale survives a failed pass either.
      vtkFRepInformation::Remove(info);
      // Every rank builds the whole object: it cannot be split into pieces.
      info->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
    }
    for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
    {
      for (int i = 0; i < inInfo[port]->GetNumberOfInformationObjects(); ++i)
      {
        vtkFRepInformation::CompleteInputInformation(inInfo[port]->GetInformationObject(i));
      }
    }
    return this->RequestInformation(request, inInfo, outInfo);
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    return this->RequestUpdateExtent(request, inInfo, outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inInfo, outInfo);
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::RequestDataObject(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* portInfo = this->GetOutputPortInformation(port);
    const char* type = portInfo->Get(vtkDataObject::DATA_TYPE_NAME());
    if (!type || std::strcmp(type, "vtkFRepObject") != 0)
    {
      continue; // another kind of output: the subclass makes it
    }
    vtkInformation* info = outInfo->GetInformationObject(port);
    if (!vtkFRepObject::GetData(info))
    {
      vtkNew<vtkFRepObject> output;
      info->Set(vtkDataObject::DATA_OBJECT(), output);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkInformation* input = this->GetNumberOfInputPorts() > 0 && inInfo[0]
    ? inInfo[0]->GetInformationObject(0)
    : nullptr;
  vtkFRepInformation::Metadata metadata;
  if (!vtkFRepInformation::Get(input, metadata))
  {
    return 1; // no object upstream (reported there): no object here
  }
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    if (vtkFRepObject::GetData(outInfo, port))
    {
      vtkFRepInformation::Set(outInfo->GetInformationObject(port), metadata);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector*)
{
  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    for (int i = 0; i < inInfo[port]->GetNumberOfInformationObjects(); ++i)
    {
      vtkFRepInformation::RequestWholeObject(inInfo[port]->GetInformationObject(i));
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepObjectAlgorithm::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepObjectAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
