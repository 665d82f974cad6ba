// The model panel: the object picker, a slider + spin box per coordinate beyond x1..x3 (the
// cross-section's fixed values), each with a "projected" box (the section is then the union over
// the slider's range: the model projected along that coordinate) and a field per parameter a[i].
// Values and projected boxes are remembered by name, so editing the model (which rebuilds the
// panel) keeps where the user was.
#pragma once

#include "CoordinateRanges.h"

#include "Project/projection.h"

#include <QWidget>

#include <map>
#include <set>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QSlider;

namespace frepstudio
{

class CoordinatePanel : public QWidget
{
  Q_OBJECT
public:
  explicit CoordinatePanel(QWidget* parent = nullptr);

  /// Lists the objects; keeps the current one when it is still there, else selects `fallback`.
  void setObjects(const std::vector<std::string>& names, int fallback);
  /// The selected object's name ("" when none).
  std::string currentObject() const;
  /// Selects an object by name (case-insensitive); false when there is none of that name.
  bool selectObject(const std::string& name);

  /// Rebuilds the sliders for x4..x[x_dim] and the a[1..a_dim] fields.
  void setModelShape(int x_dim, int a_dim, const CoordinateRanges& ranges);

  /// x4..x[x_dim] as set now.
  std::vector<double> fixedValues() const;
  /// The coordinates whose "projected" box is ticked, over their sliders' ranges (1-based, in
  /// increasing order; empty: none). Their fixedValues() are read by nothing.
  std::vector<frep::project::CoordinateRange> projectedRanges() const;
  /// a[1..a_dim] as set now.
  std::vector<double> parameters() const;

  /// Sets coordinate `name` ("x4") or parameter ("a1"). A name the model does not have (yet) is
  /// remembered and applied when it appears. Returns false for a malformed name.
  bool setValue(const std::string& name, double value);
  /// Ticks or clears coordinate `name`'s ("x4") projected box; remembered for a coordinate the
  /// model does not have (yet). Returns false for a malformed name.
  bool setProjected(const std::string& name, bool projected);
  /// The slider of coordinate x[index + 1] (index >= 3), or null (for tests).
  QSlider* slider(int index) const;
  int sliderCount() const { return static_cast<int>(sliders_.size()); }

signals:
  void objectChanged();
  /// A slider, spin box or parameter changed (by the user or setValue).
  void valuesChanged();

private:
  struct Coordinate
  {
    std::string name;
    double lo = 0, hi = 1;
    QSlider* slider = nullptr;
    QDoubleSpinBox* spin = nullptr;
    QCheckBox* projected = nullptr;
  };
  void addCoordinateRow(Coordinate coordinate, double value);
  void clearForm(QFormLayout* form);
  double remembered(const std::string& name, double fallback) const;

  QComboBox* objects_ = nullptr;
  QGroupBox* coordinate_box_ = nullptr;
  QFormLayout* coordinate_form_ = nullptr;
  QGroupBox* parameter_box_ = nullptr;
  QFormLayout* parameter_form_ = nullptr;
  std::vector<Coordinate> sliders_;
  std::vector<QDoubleSpinBox*> parameters_;
  std::map<std::string, double> values_; ///< every value set, by name ("x4", "a1")
  std::set<std::string> projected_;      ///< the coordinates projected, by name
};

} // namespace frepstudio
