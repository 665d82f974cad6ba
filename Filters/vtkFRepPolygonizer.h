/**
 * @class   vtkFRepPolygonizer
 * @brief   vtkFRepObject (3-D or 2-D) -> the surface F = IsoValue as vtkPolyData
 *
 * vtkFRepPolygonizer meshes the solid F >= IsoValue of a 3-D vtkFRepObject (triangles) or
 * contours a 2-D one (line segments, z = 0), with FRepKit's extractor (frep::mesh): the grid of
 * SampleDimensions over ModelBounds is walked in boxes whose interval enclosure of F decides
 * whether they can hold the surface; only those are sampled (batch evaluation on all cores) and
 * polygonised, so time and memory grow with the surface, not the volume.
 *
 * The mesh is watertight and consistently oriented, outward (towards smaller F): marching cubes
 * whose ambiguous faces are decided from the face's own four values, so the two cells of a face
 * always agree; points are shared through their grid edge (no duplicates, no cracks between
 * blocks or threads). Where the solid meets the box it is closed by caps on the box faces
 * (CapBoundary, on by default). 2-D contours are oriented with the inside on their left.
 *
 * Point arrays: "Normals" (outward unit normals from the model's gradient, set as the normals;
 * ComputeNormals), "s" (the model's s[1..s_dim] at the point, s_dim components;
 * ComputeAttributes, only when the model has s[]). Run-time errors in the model make the point
 * outside (NaN); their count is reported once per execution as a warning.
 *
 * Piece requests are honoured: piece p of n polygonises a slab of the grid's cells along z
 * (the caps stay on the whole box), so the pieces of a distributed run together give the same
 * triangles as one process (points on slab boundaries appear in both pieces).
 *
 * Requests with more grid points than MaximumNumberOfSamples are refused before any work (an
 * error, empty output). Progress is reported and AbortExecute is honoured between blocks.
 *
 * @sa vtkFRepObject vtkFRepSampler vtkFRepSlice vtkFRepImplicitFunction
 */
#ifndef vtkFRepPolygonizer_h
#define vtkFRepPolygonizer_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include "Sample/grid.h" // for frep::max_grid_samples

#include <cstddef> // for std::size_t

class vtkPolyData;
namespace frep
{
namespace mesh
{
struct Surface;
}
}

class FREPKITFILTERS_EXPORT vtkFRepPolygonizer : public vtkPolyDataAlgorithm
{
public:
  static vtkFRepPolygonizer* New();
  vtkTypeMacro(vtkFRepPolygonizer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The box (xmin, xmax, ymin, ymax, zmin, zmax) sampled. Default (0, -1, 0, -1, 0, -1): an
   * axis whose min > max takes the object's interval of that coordinate
   * (vtkFRepObject::GetEvaluationDescription().Ranges), as vtkFRepSampler does. min == max is
   * an error. For a 2-D object the z values are ignored.
   */
  vtkSetVector6Macro(ModelBounds, double);
  vtkGetVector6Macro(ModelBounds, double);
  ///@}

  ///@{
  /**
   * Grid samples per axis (default 64, 64, 64; at least 2 each; the third is ignored for a
   * 2-D object). Sample i of an axis is at min + i * (max - min) / (samples - 1).
   */
  vtkSetVector3Macro(SampleDimensions, int);
  vtkGetVector3Macro(SampleDimensions, int);
  ///@}

  ///@{
  /**
   * The surface is F = IsoValue; F >= IsoValue is the solid (default 0).
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /**
   * Close the solid with caps where it meets the box (default on; 3-D only).
   */
  vtkSetMacro(CapBoundary, vtkTypeBool);
  vtkGetMacro(CapBoundary, vtkTypeBool);
  vtkBooleanMacro(CapBoundary, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Point normals from the model's gradient (default on; 3-D only).
   */
  vtkSetMacro(ComputeNormals, vtkTypeBool);
  vtkGetMacro(ComputeNormals, vtkTypeBool);
  vtkBooleanMacro(ComputeNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The model's s[] attributes at the points, array "s" (default on).
   */
  vtkSetMacro(ComputeAttributes, vtkTypeBool);
  vtkGetMacro(ComputeAttributes, vtkTypeBool);
  vtkBooleanMacro(ComputeAttributes, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Interval culling (default on). Off samples every grid point: the same mesh, slower; for
   * tests and measurements.
   */
  vtkSetMacro(Culling, vtkTypeBool);
  vtkGetMacro(Culling, vtkTypeBool);
  vtkBooleanMacro(Culling, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Root refinement steps per point along its grid edge (default 0: linear interpolation).
   */
  vtkSetClampMacro(RefinementSteps, int, 0, 64);
  vtkGetMacro(RefinementSteps, int);
  ///@}

  ///@{
  /**
   * Largest grid accepted (default 4096^3 = 68719476736 points, frep::max_grid_samples: the
   * engine's one grid limit).
   */
  vtkSetMacro(MaximumNumberOfSamples, double);
  vtkGetMacro(MaximumNumberOfSamples, double);
  ///@}

  ///@{
  /**
   * Threads (default 0: all cores; the engine's own pool, whatever VTK's SMP backend is).
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Precision of the output points: vtkAlgorithm::SINGLE_PRECISION (default) or
   * DOUBLE_PRECISION (DEFAULT_PRECISION means single).
   */
  vtkSetMacro(OutputPointsPrecision, int);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * What the last execution did: grid points evaluated, boxes proven inside or outside,
   * points whose evaluation failed (NaN, outside).
   */
  std::size_t GetNumberOfEvaluatedSamples() const { return this->EvaluatedSamples; }
  std::size_t GetNumberOfCulledBoxes() const { return this->CulledBoxes; }
  std::size_t GetNumberOfFailedSamples() const { return this->FailedSamples; }
  ///@}

  /**
   * An engine mesh (frep::mesh::Surface) as vtkPolyData, the way this filter outputs it:
   * points in `precision` (vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION), triangles (3-D)
   * or lines (2-D) as one offsets + connectivity pair, "Normals" (set as the normals) and "s"
   * (s_dim components) when the surface has them. Replaces `output`'s points, cells and point
   * data. Shared by every FRepKit producer of meshes (vtkMultimediaMapper, FRepStudio).
   */
  static void ConvertSurface(
    const frep::mesh::Surface& surface, int precision, vtkPolyData* output);

protected:
  vtkFRepPolygonizer();
  ~vtkFRepPolygonizer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ModelBounds[6] = { 0, -1, 0, -1, 0, -1 };
  int SampleDimensions[3] = { 64, 64, 64 };
  double IsoValue = 0.0;
  vtkTypeBool CapBoundary = 1;
  vtkTypeBool ComputeNormals = 1;
  vtkTypeBool ComputeAttributes = 1;
  vtkTypeBool Culling = 1;
  int RefinementSteps = 0;
  double MaximumNumberOfSamples = frep::max_grid_samples;
  int NumberOfThreads = 0;
  int OutputPointsPrecision = vtkAlgorithm::SINGLE_PRECISION;

private:
  vtkFRepPolygonizer(const vtkFRepPolygonizer&) = delete;
  void operator=(const vtkFRepPolygonizer&) = delete;

  std::size_t EvaluatedSamples = 0;
  std::size_t CulledBoxes = 0;
  std::size_t FailedSamples = 0;
};

#endif
