/**
 * @class   vtkMultimediaMapper
 * @brief   n-D vtkFRepObject + multimedia mapping -> the cross-sections of the cells or frames
 *
 * vtkMultimediaMapper turns an n-D FRep object into its multimedia pieces, as a
 * vtkMultimediaMapping says: the world coordinates stay free and span the elementary shape,
 * every other coordinate takes its value per spreadsheet cell (the spreadsheet coordinates'
 * nodes) or per animation frame (the point of the path of the dynamic coordinates at the
 * frame's time), or a fixed value.
 *
 * The output is a vtkPartitionedDataSetCollection with one partitioned data set per cell
 * (OutputMode Spreadsheet, the default; column fastest, then row, then layer) or the one frame
 * at the requested time (OutputMode Frame). Each holds one vtkPolyData: the section's surface
 * in world space (watertight, outward normals "Normals" from the model's gradient, colours
 * "Colors" as unsigned char RGB per point from the mapping's colour channels or the model's
 * s[]), moved by the cell's transformation channels. Its field data name the sample:
 * "CellIndex" (3 ints, -1 unused), "Time" (s), "PathParameter", "CoordinateNames" and
 * "CoordinateValues" (per model coordinate, NaN for the world ones), "Label", "Colour" (RGB),
 * "Opacity", "Background", "LightIntensity", "Transform" (16, row-major), "WorldBounds" (6: the box
 * of every cell and frame), and the sound of the sample: "VoicePitch", "VoiceLoudness",
 * "VoiceTimbre" (one tuple per voice) and, for a frame, "AudioSamples" (its 1/fps seconds of
 * the mono sound track, floats in [-1, 1], the samples `frepkit map` writes to the WAV) with
 * "AudioSampleRate". The data set's metadata NAME is the label, e.g. "x4 = 0.25, x5 = 0.5". The
 * cross-section as an FRep object is the input with the cell's CoordinateValues fixed
 * (vtkFRepSlice), which is how the mesh is made.
 *
 * Time: with OutputMode Frame and a mapping with dynamic coordinates, RequestInformation
 * publishes TIME_STEPS (frame k at k / fps) and TIME_RANGE, and RequestData meshes the frame of
 * UPDATE_TIME_STEP (the last frame at or before it; the first frame without a request), so
 * ParaView's animation toolbar and VTK's time-aware writers play the animation. The plan (and so
 * TIME_STEPS) is made from the input's vtkFRepInformation keys (coordinate names, intervals,
 * fixed values, a[]), which the FRep producers publish in their own information pass: the
 * information pass executes nothing upstream.
 *
 * Pieces (CAN_HANDLE_PIECE_REQUEST): piece p of n meshes the samples i with i % n == p and
 * leaves the others as empty partitioned data sets (same structure and names on every rank), so
 * `mpiexec -n 2 pvbatch` shares the cells between the ranks and together they hold every cell
 * once.
 *
 * The section of each sample is the engine's specialisation of the model (a 3-D tape) meshed
 * with interval culling on all cores (frep::mapping::make_section), the same code that
 * `frepkit map` runs. A mapping that does not fit the object (an unmapped coordinate, a name
 * the object lacks, ...) gives one vtkErrorMacro listing every problem with its place and an
 * empty output. Progress is reported per sample; AbortExecute is honoured between samples and
 * inside the meshing.
 *
 * @sa vtkMultimediaMapping vtkSpreadsheetLayout vtkFRepObject vtkFRepInformation vtkFRepPolygonizer
 */
#ifndef vtkMultimediaMapper_h
#define vtkMultimediaMapper_h

#include "FRepKitMappingModule.h" // for export macro
#include "vtkPartitionedDataSetCollectionAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkMultimediaMapping;

class FREPKITMAPPING_EXPORT vtkMultimediaMapper : public vtkPartitionedDataSetCollectionAlgorithm
{
public:
  static vtkMultimediaMapper* New();
  vtkTypeMacro(vtkMultimediaMapper, vtkPartitionedDataSetCollectionAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mapping (default none: an error on execution unless MappingFileName is set).
   */
  virtual void SetMapping(vtkMultimediaMapping*);
  vtkGetObjectMacro(Mapping, vtkMultimediaMapping);
  ///@}

  ///@{
  /**
   * A JSON mapping file read on execution when no Mapping object is set (for ParaView).
   * Default none.
   */
  vtkSetStringMacro(MappingFileName);
  vtkGetStringMacro(MappingFileName);
  ///@}

  enum OutputModes
  {
    SPREADSHEET = 0, ///< every spreadsheet cell
    FRAME = 1,       ///< the animation frame at the requested time
  };

  ///@{
  /**
   * What to produce (default SPREADSHEET).
   */
  vtkSetClampMacro(OutputMode, int, SPREADSHEET, FRAME);
  vtkGetMacro(OutputMode, int);
  void SetOutputModeToSpreadsheet() { this->SetOutputMode(SPREADSHEET); }
  void SetOutputModeToFrame() { this->SetOutputMode(FRAME); }
  ///@}

  ///@{
  /**
   * Grid samples along the longest world axis; 0 (default) takes the mapping's
   * world.resolution (128 unless the file says otherwise).
   */
  vtkSetClampMacro(Resolution, int, 0, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Threads of the meshing (default 0: all cores; the engine's pool, whatever VTK's SMP
   * backend is).
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Frames of the mapping as last planned (0 without dynamic coordinates), and cells.
   */
  int GetNumberOfFrames() const;
  int GetNumberOfCells() const;

  /**
   * Samples this piece meshed in the last execution (all of them in a serial run; about 1/n
   * of them as piece p of n).
   */
  int GetNumberOfSamplesMeshed() const { return this->SamplesMeshed; }

  vtkMTimeType GetMTime() override;

protected:
  vtkMultimediaMapper();
  ~vtkMultimediaMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkMultimediaMapping* Mapping = nullptr;
  char* MappingFileName = nullptr;
  int OutputMode = SPREADSHEET;
  int Resolution = 0;
  int NumberOfThreads = 0;
  int SamplesMeshed = 0;

private:
  vtkMultimediaMapper(const vtkMultimediaMapper&) = delete;
  void operator=(const vtkMultimediaMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
