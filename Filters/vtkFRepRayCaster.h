/**
 * @class   vtkFRepRayCaster
 * @brief   draws a 3-D FRep object by rays: a picture as vtkImageData with "Colour" and "Depth"
 *
 * vtkFRepRayCaster renders the solid F >= 0 of a 3-D vtkFRepObject directly from its function,
 * without a mesh, with FRepKit's ray caster (frep::raycast::render, FRep/Raycast/raycast.h):
 * every pixel casts a ray and finds the first point where F >= 0 (interval-pruned search and
 * root refinement on the object's specialised tape), shaded with the gradient's normal under the
 * mesh renderer's light kit. The solid is cut by ModelBounds; where it meets the box the cut
 * faces are drawn as caps (as vtkFRepPolygonizer closes its meshes). Slice an n-D object with
 * vtkFRepSlice first: an object whose dimension is not 3 is refused with one vtkErrorMacro.
 *
 * OUTPUT: a 2-D vtkImageData of Width x Height x 1 points (extent 0..Width-1, 0..Height-1,
 * 0..0, origin 0, spacing 1: one point per pixel), the picture's top row at j = Height - 1 (VTK's
 * images grow upwards), with the point arrays
 * - "Colour" (the active scalars): unsigned char, 4 components R, G, B, A; sRGB-encoded colour,
 *   straight (not premultiplied) alpha: the shape's shading composited over Background (an
 *   edge pixel blends the two by its coverage). Shown as it is in ParaView with Map Scalars off
 *   (and by vtkImageViewer2 / a texture with direct scalars).
 * - "Depth": float, the world distance from the eye along the view direction (not along the
 *   ray: the camera-space z) of the nearest surface the pixel shows, shape or floor (an edge
 *   pixel takes the nearest of its samples); +infinity (IEEE) where nothing was hit, so
 *   std::isfinite / numpy.isfinite tells covered pixels from the background.
 *
 * CAMERA: the one frep::imaging::fit_box makes from the direction (Azimuth, Elevation): with z
 * up, Elevation is the angle above the xy plane and Azimuth turns counter-clockwise about +z
 * starting from -y (Azimuth 0, Elevation 0 looks along +y with x to the right; 90 looks along
 * -x). It frames the solid, not the box (FrameSolid, the default): the solid as seen from
 * that direction (frep::raycast::silhouette: 64 x 64 rays along the view over the solid's
 * bounds in the box, frep::raycast::solid_bounds, the search the ray caster clips its rays to,
 * done once per execution) fills 90 % of the picture's width or height (frep::render::
 * fit_points), so a unit ball in the default box [-10, 10]^3 fills the picture as it would in a
 * box of its own size. With FrameSolid off, or when no ray meets the solid, it frames the
 * bounding sphere of the box (or of the solid's bounds) to 90 % of the shorter side (fit_box:
 * with FrameSolid off the camera depends on the box only, the same for every object, e.g. over
 * an animation). With Floor on, the floor's squares are framed too. Perspective with
 * ViewAngle, or parallel with ParallelProjection. The camera needs the object's function, so
 * it is fitted in the data pass; that of the last execution is readable (GetCameraPosition,
 * ...), e.g. to turn Depth back into world points. Model coordinates are world coordinates
 * (no transform).
 *
 * PIPELINE: RequestInformation reads the object's dimension and intervals from the
 * vtkFRepInformation keys its producer publishes (an input given as data is described from the
 * object) and sets the whole extent from Width and Height: nothing upstream executes before the
 * data pass. The whole picture is drawn by every execution (no sub-extents). An empty input (an
 * upstream error, reported there) gives an empty image without a message; a refused request
 * (dimension, bounds, view) one error and an empty image (empty whole extent).
 *
 * PROGRESS AND ABORT: UpdateProgress(0) when the data pass starts, then rising fractions as
 * the ray caster's tiles finish (reported on the executing thread only: the pixel pass is the
 * first 70 %, the edge pixels' supersampling the rest) and 1 when the picture is complete. The
 * ray caster polls a cancel
 * callback per tile of 16 x 16 pixels from its worker threads: on the thread that executes the
 * filter it calls CheckAbort() (VTK's full check: AbortExecute, the container algorithm, an
 * aborted upstream), which must not run elsewhere; every thread also reads the atomic
 * AbortExecute flag directly (in VTK 9.2 a public std::atomic), and a cancellation seen by one
 * thread stops the others. An aborted execution leaves an empty image.
 *
 * The picture does not depend on NumberOfThreads (the ray caster's guarantee: each sample's
 * search depends only on its own ray).
 *
 * @sa vtkFRepObject vtkFRepSlice vtkFRepPolygonizer vtkFRepSampler
 */
#ifndef vtkFRepRayCaster_h
#define vtkFRepRayCaster_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <cstddef> // for std::size_t
#include <memory>  // for std::unique_ptr

class FREPKITFILTERS_EXPORT vtkFRepRayCaster : public vtkImageAlgorithm
{
public:
  static vtkFRepRayCaster* New();
  vtkTypeMacro(vtkFRepRayCaster, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The picture's size in pixels (default 640 x 480; each 1..16384, as `frepkit render`).
   */
  vtkSetClampMacro(Width, int, 1, 16384);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 1, 16384);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * The view direction in degrees (default Azimuth 35, Elevation 25, as `frepkit render`): see
   * CAMERA in the class description. Must be finite (else an error).
   */
  vtkSetMacro(Azimuth, double);
  vtkGetMacro(Azimuth, double);
  vtkSetMacro(Elevation, double);
  vtkGetMacro(Elevation, double);
  ///@}

  ///@{
  /**
   * The full vertical view angle of the perspective camera, degrees (default 30, 1..170).
   */
  vtkSetClampMacro(ViewAngle, double, 1.0, 170.0);
  vtkGetMacro(ViewAngle, double);
  ///@}

  ///@{
  /**
   * Parallel (orthographic) projection instead of perspective (default off).
   */
  vtkSetMacro(ParallelProjection, vtkTypeBool);
  vtkGetMacro(ParallelProjection, vtkTypeBool);
  vtkBooleanMacro(ParallelProjection, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The model box (xmin, xmax, ymin, ymax, zmin, zmax) the solid is cut by (and the camera
   * frames, with FrameSolid off). Default (0, -1, 0, -1, 0, -1): an axis with min > max takes the
   * object's interval of that coordinate (the vtkFRepInformation COORDINATE_RANGES of its producer,
   * [-10, 10] unless the source set others), as vtkFRepSampler and vtkFRepPolygonizer do. The
   * resolved box must be finite with min < max on every axis (else an error).
   */
  vtkSetVector6Macro(ModelBounds, double);
  vtkGetVector6Macro(ModelBounds, double);
  ///@}

  ///@{
  /**
   * The shape's colour, sRGB components 0..1 (default 0.85, 0.62, 0.38, `frepkit render`'s;
   * values are clamped to 0..1 when drawing).
   */
  vtkSetVector3Macro(Colour, double);
  vtkGetVector3Macro(Colour, double);
  ///@}

  ///@{
  /**
   * The picture's background, sRGB components and alpha 0..1 (default 1, 1, 1, 1: opaque
   * white; alpha 0 gives a transparent background, whose Colour alpha is then the coverage).
   * Clamped to 0..1 when drawing.
   */
  vtkSetVector4Macro(Background, double);
  vtkGetVector4Macro(Background, double);
  ///@}

  ///@{
  /**
   * Rays per pixel along each axis at edges (default 2; 1..4): pixels whose first ray sees
   * something else than a neighbour's get Supersample^2 rays, averaged.
   */
  vtkSetClampMacro(Supersample, int, 1, 4);
  vtkGetMacro(Supersample, int);
  ///@}

  ///@{
  /**
   * A checkerboard floor under the shape with its shadow (default off): the plane z = the
   * solid's lowest point (raycast::lowest_z, so the shape stands on it), 8 x 8 squares over 1.6
   * times the framed box's larger side in x and y (the solid's bounds, or the box with
   * FrameSolid off), centred under it, as `frepkit render --floor`; the camera then frames the
   * floor too.
   */
  vtkSetMacro(Floor, vtkTypeBool);
  vtkGetMacro(Floor, vtkTypeBool);
  vtkBooleanMacro(Floor, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The camera frames the solid's bounds inside the box (default on) or, off, the whole box:
   * see CAMERA in the class description.
   */
  vtkSetMacro(FrameSolid, vtkTypeBool);
  vtkGetMacro(FrameSolid, vtkTypeBool);
  vtkBooleanMacro(FrameSolid, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The shape's shadows on itself from the key light (default off; one more ray per lit
   * sample).
   */
  vtkSetMacro(SelfShadows, vtkTypeBool);
  vtkGetMacro(SelfShadows, vtkTypeBool);
  vtkBooleanMacro(SelfShadows, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Threads that trace (the participants of the engine's thread pool, the calling thread
   * included); default 0 = every core, 1 = the calling thread only; at most 1024, as the other
   * filters. The picture does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * The camera of the last execution (world = model coordinates): eye, focal point (framing
   * the solid: on the view axis through the middle of its outline, at the depth of the centre
   * of its bounds — a ball's centre; framing the box: its centre), view up, and for a parallel
   * projection the world distance from the picture's centre to its top edge. All zero before the
   * first execution and after a refused request; an information pass alone does not fit the camera
   * (it needs the function).
   */
  vtkGetVector3Macro(CameraPosition, double);
  vtkGetVector3Macro(CameraFocalPoint, double);
  vtkGetVector3Macro(CameraViewUp, double);
  vtkGetMacro(CameraParallelScale, double);
  ///@}

  ///@{
  /**
   * What the last execution did (the ray caster's statistics): primary and edge rays cast, and
   * the rays that met the solid. 0 before the first execution; an aborted execution reports
   * the rays it cast before it stopped.
   */
  vtkIdType GetNumberOfRays() const { return static_cast<vtkIdType>(this->Rays); }
  vtkIdType GetNumberOfHits() const { return static_cast<vtkIdType>(this->Hits); }
  ///@}

protected:
  /**
   * Defaults: Width 640, Height 480, Azimuth 35, Elevation 25, ViewAngle 30, ParallelProjection
   * off, ModelBounds (0, -1, 0, -1, 0, -1) = the object's intervals, Colour (0.85, 0.62, 0.38),
   * Background (1, 1, 1, 1), Supersample 2, Floor off, FrameSolid on, SelfShadows off,
   * NumberOfThreads 0 (all cores). One input port (vtkFRepObject), one output port (vtkImageData).
   */
  vtkFRepRayCaster();
  ~vtkFRepRayCaster() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Width = 640;
  int Height = 480;
  double Azimuth = 35.0;
  double Elevation = 25.0;
  double ViewAngle = 30.0;
  vtkTypeBool ParallelProjection = 0;
  double ModelBounds[6] = { 0, -1, 0, -1, 0, -1 };
  double Colour[3] = { 0.85, 0.62, 0.38 };
  double Background[4] = { 1.0, 1.0, 1.0, 1.0 };
  int Supersample = 2;
  vtkTypeBool Floor = 0;
  vtkTypeBool FrameSolid = 1;
  vtkTypeBool SelfShadows = 0;
  int NumberOfThreads = 0;

  double CameraPosition[3] = { 0, 0, 0 };
  double CameraFocalPoint[3] = { 0, 0, 0 };
  double CameraViewUp[3] = { 0, 0, 0 };
  double CameraParallelScale = 0.0;

private:
  vtkFRepRayCaster(const vtkFRepRayCaster&) = delete;
  void operator=(const vtkFRepRayCaster&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  std::size_t Rays = 0;
  std::size_t Hits = 0;
};

#endif
