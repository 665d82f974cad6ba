/**
 * @class   vtkFRepObjectAlgorithm
 * @brief   superclass for algorithms that produce vtkFRepObject
 *
 * vtkFRepObjectAlgorithm is to vtkFRepObject what vtkPolyDataAlgorithm is to vtkPolyData: it
 * holds the pipeline boilerplate of every FRep producer (vtkHyperFunSource, vtkHyperFunReader,
 * vtkFRepSlice, vtkFRepBoolean), and subclasses override RequestInformation and RequestData.
 *
 * - ProcessRequest dispatches REQUEST_DATA_OBJECT, REQUEST_INFORMATION, REQUEST_UPDATE_EXTENT
 *   and REQUEST_DATA to the virtual methods below.
 * - RequestDataObject makes a vtkFRepObject on every output port whose DATA_TYPE_NAME is
 *   vtkFRepObject (the default of FillOutputPortInformation); a subclass with other outputs
 *   makes those itself.
 * - Before RequestInformation, every output loses the vtkFRepInformation keys (a failed pass
 *   leaves no stale description) and gets CAN_HANDLE_PIECE_REQUEST: every rank of a parallel run
 *   builds the whole object, which cannot be split into pieces or sent between ranks. Every input
 *   given as data (a vtkTrivialProducer) is described from its object
 *   (vtkFRepInformation::CompleteInputInformation), so subclasses read keys only.
 * - RequestInformation, by default, describes each vtkFRepObject output as the first input
 *   (the keys unchanged) and a source's outputs as no object. A producer sets the keys of what
 *   it will produce (vtkFRepInformation), from its parameters and its inputs' keys, without
 *   executing anything upstream: this is what lets a sampler or a mapper plan its output (whole
 *   extent, time steps) from information alone.
 * - RequestUpdateExtent asks every input for the whole object, always the same request (piece
 *   0 of 1), so that upstream never re-executes because of pieces.
 * - RequestData does nothing by default.
 *
 * Ports: FillInputPortInformation requires vtkFRepObject on every input port,
 * FillOutputPortInformation declares vtkFRepObject on every output port. The constructor makes
 * one input port and one output port; subclasses set their own numbers.
 *
 * @sa vtkFRepObject vtkFRepInformation vtkHyperFunSource
 */
#ifndef vtkFRepObjectAlgorithm_h
#define vtkFRepObjectAlgorithm_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkAlgorithm.h"

class vtkDataObject;
class vtkFRepObject;

class FREPKITSOURCES_EXPORT vtkFRepObjectAlgorithm : public vtkAlgorithm
{
public:
  static vtkFRepObjectAlgorithm* New();
  vtkTypeMacro(vtkFRepObjectAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The output on port 0 / on `port`: null when that port's data object is not a
   * vtkFRepObject (or does not exist yet).
   */
  vtkFRepObject* GetOutput();
  vtkFRepObject* GetOutput(int port);
  ///@}

  ///@{
  /**
   * An input without a pipeline connection (a vtkFRepObject) on port 0 / on `port`. It is
   * described to the pipeline from the object itself (see the class description).
   */
  void SetInputData(vtkDataObject* input);
  void SetInputData(int port, vtkDataObject* input);
  ///@}

  /**
   * Dispatches REQUEST_DATA_OBJECT, REQUEST_INFORMATION, REQUEST_UPDATE_EXTENT and
   * REQUEST_DATA (see the class description).
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

protected:
  /**
   * Defaults: one input port and one output port, both vtkFRepObject.
   */
  vtkFRepObjectAlgorithm();
  ~vtkFRepObjectAlgorithm() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

private:
  vtkFRepObjectAlgorithm(const vtkFRepObjectAlgorithm&) = delete;
  void operator=(const vtkFRepObjectAlgorithm&) = delete;
};

#endif
