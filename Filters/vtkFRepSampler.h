/**
 * @class   vtkFRepSampler
 * @brief   samples a 2-D or 3-D FRep object on a regular grid: vtkImageData with "F"
 *
 * vtkFRepSampler evaluates the function F of a vtkFRepObject whose dimension (number of free
 * coordinates) is 2 or 3 at the points of a regular grid, and produces a vtkImageData with the
 * point array "F" (the active scalars). Axis i of the image is free coordinate i of the
 * object (slice an n-D object with vtkFRepSlice first). A 2-D object gives an image with one
 * sample along z (SampleDimensions[2] is then ignored, the z origin is 0 and the z spacing 1).
 *
 * SIGN CONVENTION: F is FRep's, positive inside, 0 on the surface, negative outside (not
 * negated as vtkFRepImplicitFunction does for VTK's implicit functions). Contour F = 0.
 *
 * SAMPLE POSITIONS: with lo, hi the bounds of an axis and n its number of samples,
 *   spacing = (hi - lo) / (n - 1)   (1 when n == 1; frep::grid_step),
 *   position of sample i = lo + i * spacing   (i the global index, 0..n-1; see SamplePosition),
 * the engine's one position formula (FRep/Sample/grid.h, frep::grid_coordinate, which the
 * mesher and frepkit slice use too), computed exactly this way for every sample of every
 * extent, so a value
 * equals frep::PointEvaluator's at that position bit for bit (and the image's origin and
 * spacing reproduce the position: vtkImageData::GetPoint). The last sample lies at hi up to
 * rounding. The bounds are ModelBounds; an axis whose ModelBounds have lo > hi (the default for
 * every axis) takes the interval of the object's coordinate on that axis
 * (vtkFRepObject::GetEvaluationDescription().Ranges, [-10, 10] unless the source set others).
 *
 * ARRAYS (all of OutputScalarType): "F" (1 component) always; with ComputeGradients,
 * "Gradient" (3 components, dF/dx, dF/dy, dF/dz; dF/dz = 0 for a 2-D object); with
 * ComputeNormals, "Normals" (3 components, the outward unit normal -grad F / |grad F|, since F
 * is positive inside; (0, 0, 0) where the gradient is zero or not finite), set as the image's
 * normals; with ComputeAttributes, "s" (s_dim components: the model's s[1..s_dim] at the
 * point, as the tape computes them from s[] = 0; a header without s[] has s_dim 1, so the
 * array then holds s[1] = 0). Gradients are exact (forward-mode differentiation,
 * frep::GradientEvaluator).
 *
 * RUN-TIME ERRORS (Documentation/compatibility.md, "Run-time errors: the policy"): a sample
 * whose evaluation raised a run-time error (sqrt of a negative number, division by ~0, ...) or
 * gave NaN has F = NaN (outside), and NaN in every other array, unless HfpErrors is on: then,
 * as hfp does, it takes the previous sample's values (previous in the image's point order, x
 * fastest, within the extent being computed; 0 for a failure at the first sample of the
 * extent), so with HfpErrors the values of failed samples can depend on how the image is split
 * into extents. Either way the failed samples are counted (GetNumberOfEvaluationErrors) and
 * reported by ONE vtkWarningMacro per execution: the count, the first failed sample's position
 * and the error's message with its file:line:col.
 *
 * LIMITS: SampleDimensions below 1, bounds that are not finite, a zero-width axis with more
 * than one sample, or more than MaximumNumberOfSamples samples in all (default 2^31; the
 * product is computed without overflow) are refused in RequestInformation, before anything is
 * allocated, by one vtkErrorMacro; the whole extent is then empty and so is the output. An
 * object whose dimension is not 2 or 3 is refused the same way. An empty input (an upstream
 * error, reported there) gives an empty image without a further message.
 *
 * PIPELINE: RequestInformation plans the grid (whole extent, origin and spacing) from the
 * object's dimension and intervals, which its producer publishes as vtkFRepInformation keys in
 * its own information pass: nothing upstream executes before the data pass (an input given as
 * data, SetInputData, is described from the object). The sampler always requests piece 0 of 1
 * of its input, since every rank builds the whole object anyway. The output sets
 * CAN_PRODUCE_SUB_EXTENT and only
 * the requested UPDATE_EXTENT is computed: an image split over ranks or streamed in pieces has
 * exactly the values of the whole image.
 *
 * SPEED: the image is computed by the engine's grid sampler (frep::sample_grid,
 * FRep/Sample/grid_sampler.h) in blocks of 2^16 samples: per block the coordinates are
 * generated (no full-volume coordinate arrays), F and s[] are evaluated by
 * frep::BatchEvaluator (SIMD lanes), gradients by one frep::GradientEvaluator per thread, all
 * on the engine's frep::ThreadPool with NumberOfThreads participants (default 0 = every core).
 * Progress is reported after each block and CheckAbort() is honoured between blocks (an aborted
 * execution leaves an empty image).
 *
 * @sa vtkFRepObject vtkFRepSlice vtkHyperFunSource vtkSampleFunction vtkFRepImplicitFunction
 */
#ifndef vtkFRepSampler_h
#define vtkFRepSampler_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkFRepInformation.h" // for vtkFRepInformation::Metadata
#include "vtkImageAlgorithm.h"

#include "Sample/grid.h" // for frep::grid_coordinate

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkFRepObject;

class FREPKITFILTERS_EXPORT vtkFRepSampler : public vtkImageAlgorithm
{
public:
  static vtkFRepSampler* New();
  vtkTypeMacro(vtkFRepSampler, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The sampled box (xmin, xmax, ymin, ymax, zmin, zmax). Default (0, -1, 0, -1, 0, -1): an
   * axis with min > max takes the object's interval of that coordinate. For a 2-D object the
   * z bounds are ignored.
   */
  vtkSetVector6Macro(ModelBounds, double);
  vtkGetVector6Macro(ModelBounds, double);
  ///@}

  ///@{
  /**
   * Samples along x, y, z (default 64, 64, 64; each at least 1, else an error). For a 2-D
   * object the third is taken as 1.
   */
  vtkSetVector3Macro(SampleDimensions, int);
  vtkGetVector3Macro(SampleDimensions, int);
  ///@}

  ///@{
  /**
   * Type of every output array: VTK_DOUBLE (the default: the engine's values unchanged) or
   * VTK_FLOAT (values rounded to float). Any other type is an error and is not set.
   */
  void SetOutputScalarType(int type);
  vtkGetMacro(OutputScalarType, int);
  void SetOutputScalarTypeToDouble() { this->SetOutputScalarType(VTK_DOUBLE); }
  void SetOutputScalarTypeToFloat() { this->SetOutputScalarType(VTK_FLOAT); }
  ///@}

  ///@{
  /**
   * Adds the "Gradient" array, dF/dx (default off).
   */
  vtkSetMacro(ComputeGradients, vtkTypeBool);
  vtkGetMacro(ComputeGradients, vtkTypeBool);
  vtkBooleanMacro(ComputeGradients, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Adds the "Normals" array, the outward unit normals -grad F / |grad F| (default off).
   */
  vtkSetMacro(ComputeNormals, vtkTypeBool);
  vtkGetMacro(ComputeNormals, vtkTypeBool);
  vtkBooleanMacro(ComputeNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Adds the "s" array, the model's attributes s[1..s_dim] (default off).
   */
  vtkSetMacro(ComputeAttributes, vtkTypeBool);
  vtkGetMacro(ComputeAttributes, vtkTypeBool);
  vtkBooleanMacro(ComputeAttributes, vtkTypeBool);
  ///@}

  ///@{
  /**
   * hfp's behaviour for samples that raise run-time errors: the previous sample's values
   * (default off: NaN). See RUN-TIME ERRORS in the class description.
   */
  vtkSetMacro(HfpErrors, vtkTypeBool);
  vtkGetMacro(HfpErrors, vtkTypeBool);
  vtkBooleanMacro(HfpErrors, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The largest number of samples (whole extent) the sampler accepts (default 2^31, i.e. 16 GiB
   * for "F" in double). Larger requests are refused before allocating.
   */
  vtkSetClampMacro(MaximumNumberOfSamples, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /**
   * Threads that evaluate (the participants of the engine's thread pool, the calling thread
   * included); default 0 = std::thread::hardware_concurrency(), 1 = the calling thread only;
   * at most 1024 (as vtkFRepPolygonizer, vtkMultimediaMapper and frepkit --threads).
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Threads the last execution evaluated with (0 before the first one, or when it evaluated
   * nothing).
   */
  int GetNumberOfThreadsUsed() const { return this->NumberOfThreadsUsed; }

  /**
   * Samples of the last execution that raised run-time errors (or gave NaN).
   */
  vtkIdType GetNumberOfEvaluationErrors() const { return this->NumberOfEvaluationErrors; }

  /**
   * The position of sample `index` on an axis that starts at `origin` with `spacing`:
   * origin + index * spacing, in double precision (frep::grid_coordinate, the engine's one
   * position formula). Every sample is placed by it.
   */
  static double SamplePosition(double origin, double spacing, int index)
  {
    return frep::grid_coordinate(origin, spacing, index);
  }

protected:
  /**
   * Defaults: ModelBounds (0, -1, 0, -1, 0, -1) = the object's intervals, SampleDimensions
   * (64, 64, 64), OutputScalarType VTK_DOUBLE, ComputeGradients, ComputeNormals,
   * ComputeAttributes and HfpErrors off, MaximumNumberOfSamples 2^31, NumberOfThreads 0 (all
   * cores). One input port (vtkFRepObject), one output port (vtkImageData).
   */
  vtkFRepSampler();
  ~vtkFRepSampler() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ModelBounds[6];
  int SampleDimensions[3];
  int OutputScalarType;
  vtkTypeBool ComputeGradients;
  vtkTypeBool ComputeNormals;
  vtkTypeBool ComputeAttributes;
  vtkTypeBool HfpErrors;
  vtkIdType MaximumNumberOfSamples;
  int NumberOfThreads;

  int NumberOfThreadsUsed = 0;
  vtkIdType NumberOfEvaluationErrors = 0;

private:
  vtkFRepSampler(const vtkFRepSampler&) = delete;
  void operator=(const vtkFRepSampler&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  // Checks the request against the object's metadata and fills the grid of Internals; false
  // (with the reason in `problem`) when it must be refused.
  bool PlanGrid(const vtkFRepInformation::Metadata& object, std::string& problem);
  // Evaluates the extent `extent` into `output` (arrays of type T). False when aborted.
  template <typename T>
  bool Sample(vtkFRepObject* object, vtkImageData* output, const int extent[6]);
};

#endif
