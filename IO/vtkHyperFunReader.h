/**
 * @class   vtkHyperFunReader
 * @brief   .hf reader with two outputs: the n-D object and a default mesh of it
 *
 * vtkHyperFunReader is a vtkHyperFunSource (FileName, ModelText, ObjectName, a[] parameters,
 * coordinate intervals: everything works as there) with a second output, so that a viewer such
 * as ParaView, which cannot display a vtkFRepObject, shows the shape as soon as the file is
 * opened:
 *
 * - output port 0: the vtkFRepObject, every coordinate free (exactly vtkHyperFunSource's
 *   output; connect vtkFRepSlice, vtkFRepSampler, ... here);
 * - output port 1: a vtkPolyData, the default view of the object: for an object of dimension 3
 *   or more, the surface (vtkFRepPolygonizer with its defaults, GeometryResolution samples per
 *   axis) over the first three coordinates x1, x2, x3 inside their intervals, every further
 *   coordinate fixed at the midpoint of its interval; for a 2-D object its contour in z = 0; a
 *   1-D object gives an empty mesh. Its field data are those of the sliced object
 *   (FRepDimension, FRepFixedValues with the midpoints, ...), so an information panel shows
 *   which cross-section it is.
 *
 * The mesh is computed inside the reader (no second pipeline is exposed): the pipeline a user
 * sees stays "reader -> filters". Piece requests on port 1 are honoured as vtkFRepPolygonizer
 * honours them (piece p of n meshes a slab of the cells along z); port 0 is the whole object on
 * every piece (CAN_HANDLE_PIECE_REQUEST on both ports). With GenerateGeometry off, port 1 stays
 * empty and nothing is meshed.
 *
 * DISTRIBUTED RUNS: in a parallel run (the global vtkMultiProcessController has more than one
 * process, as in pvbatch/pvserver under mpiexec) an update of port 0 alone (Update(), Update(0),
 * or a filter on the object asking for the whole object, as every FRep filter does) does not
 * mesh port 1: port 1 is left as it was and marked not generated (DATA_NOT_GENERATED), so the
 * requests of its consumers (piece r of N on rank r) execute the reader again and mesh only
 * their piece. Without this every rank meshed the whole default mesh once, then its piece. In
 * one process nothing changes: an update of port 0 meshes port 1 for port 1's own piece request
 * (reader->Update(); reader->GetOutput(1) works); in a parallel program update port 1 itself
 * (Update(1), or a consumer's UpdatePiece).
 *
 * GetObjectNames() lists the objects the program defines, after RequestInformation (the
 * program vtkHyperFunSource parses there, once): the object the reader evaluates when
 * ObjectName is empty (my_model, else the first) comes first, then the others in the order of
 * the file; an ObjectName the program lacks still lists them. A program that does not parse
 * gives an empty list here; its diagnostics (file:line:col) are reported once, by
 * RequestInformation (vtkHyperFunSource).
 *
 * Meshing the default geometry reports progress through the reader, and AbortExecute (or an
 * observer setting it) stops it, leaving port 1 empty.
 *
 * Module FRepKit::IO (VTK keeps readers in IO modules).
 *
 * @sa vtkHyperFunSource vtkFRepPolygonizer vtkFRepSlice
 */

#ifndef vtkHyperFunReader_h
#define vtkHyperFunReader_h

#include "FRepKitIOModule.h" // for export macro
#include "vtkHyperFunSource.h"

class vtkPolyData;
class vtkStringArray;

class FREPKITIO_EXPORT vtkHyperFunReader : public vtkHyperFunSource
{
public:
  static vtkHyperFunReader* New();
  vtkTypeMacro(vtkHyperFunReader, vtkHyperFunSource);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Mesh the default cross-section on output port 1 (default on).
   */
  vtkSetMacro(GenerateGeometry, vtkTypeBool);
  vtkGetMacro(GenerateGeometry, vtkTypeBool);
  vtkBooleanMacro(GenerateGeometry, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Grid samples per axis of the mesh on port 1 (default 64; clamped to 2..1024).
   */
  vtkSetClampMacro(GeometryResolution, int, 2, 1024);
  vtkGetMacro(GeometryResolution, int);
  ///@}

  /**
   * The objects of the program, default object first (see the class description). Valid after
   * UpdateInformation(); never null.
   */
  vtkStringArray* GetObjectNames();

  /**
   * The mesh of port 1 (GetOutput() / GetOutput(0) is the vtkFRepObject).
   */
  vtkPolyData* GetGeometryOutput();

protected:
  /**
   * Defaults: as vtkHyperFunSource, GenerateGeometry on, GeometryResolution 64; two output
   * ports (vtkFRepObject, vtkPolyData).
   */
  vtkHyperFunReader();
  ~vtkHyperFunReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /**
   * Adds the REQUEST_DATA_NOT_GENERATED pass: see DISTRIBUTED RUNS in the class description.
   */
  vtkTypeBool ProcessRequest(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkTypeBool GenerateGeometry = 1;
  int GeometryResolution = 64;
  vtkStringArray* ObjectNames = nullptr;

private:
  vtkHyperFunReader(const vtkHyperFunReader&) = delete;
  void operator=(const vtkHyperFunReader&) = delete;
};

#endif
