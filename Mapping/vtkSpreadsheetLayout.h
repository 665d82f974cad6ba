/**
 * @class   vtkSpreadsheetLayout
 * @brief   the cells of a multimedia spreadsheet -> one vtkPolyData laid out on a grid
 *
 * vtkSpreadsheetLayout takes the output of vtkMultimediaMapper in its Spreadsheet mode (a
 * vtkPartitionedDataSetCollection whose data sets carry "CellIndex" in their field data) and
 * lays the cells out in one vtkPolyData, so the whole spreadsheet renders as one image:
 * column c moves by +c (1 + Spacing) W along world x, row r by -r ((1 + Spacing) D + L) along
 * world z (rows run top to bottom when world z is up; L = 1.6 LabelHeight D is room for the
 * labels when they are on), layer l by +l (1 + Spacing) H along world y, where W, H, D are the
 * sizes of the box that holds every cell (the mapper's "WorldBounds" when present, else the union
 * of the cells' bounds). Every cell is moved the same way, so the shapes stay comparable; view the
 * result with a parallel projection from -y for identical views of all cells.
 *
 * Borders (a rectangle around each cell in the plane behind it) and labels (the cell's
 * "Label", e.g. "x4 = 0.25, x5 = 0.5", as vtkVectorText geometry under the cell) are optional.
 * Point arrays: "Colors" (the cells' colours; borders and labels get LabelColor), "Normals"
 * (labels and borders face -y), and "SpreadsheetCell" (the cell's linear index; -1 for borders
 * and labels).
 *
 * @sa vtkMultimediaMapper vtkMultimediaMapping
 */
#ifndef vtkSpreadsheetLayout_h
#define vtkSpreadsheetLayout_h

#include "FRepKitMappingModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class FREPKITMAPPING_EXPORT vtkSpreadsheetLayout : public vtkPolyDataAlgorithm
{
public:
  static vtkSpreadsheetLayout* New();
  vtkTypeMacro(vtkSpreadsheetLayout, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Gap between cells, a fraction of the cell size (default 0.15).
   */
  vtkSetClampMacro(Spacing, double, 0.0, 10.0);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Rectangles around the cells (default on).
   */
  vtkSetMacro(Borders, vtkTypeBool);
  vtkGetMacro(Borders, vtkTypeBool);
  vtkBooleanMacro(Borders, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The cells' labels under them (default on).
   */
  vtkSetMacro(Labels, vtkTypeBool);
  vtkGetMacro(Labels, vtkTypeBool);
  vtkBooleanMacro(Labels, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Height of the label text, a fraction of the cell height (default 0.08).
   */
  vtkSetClampMacro(LabelHeight, double, 0.0, 1.0);
  vtkGetMacro(LabelHeight, double);
  ///@}

  ///@{
  /**
   * Colour of borders and labels, RGB 0..255 (default 40, 40, 40).
   */
  vtkSetVector3Macro(LabelColor, unsigned char);
  vtkGetVector3Macro(LabelColor, unsigned char);
  ///@}

protected:
  vtkSpreadsheetLayout();
  ~vtkSpreadsheetLayout() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Spacing = 0.15;
  vtkTypeBool Borders = 1;
  vtkTypeBool Labels = 1;
  double LabelHeight = 0.08;
  unsigned char LabelColor[3] = { 40, 40, 40 };

private:
  vtkSpreadsheetLayout(const vtkSpreadsheetLayout&) = delete;
  void operator=(const vtkSpreadsheetLayout&) = delete;
};

#endif
