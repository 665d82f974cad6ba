#include "CoordinatePanel.h"

#include "Language/names.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

namespace frepstudio
{

namespace
{
constexpr int kSliderSteps = 1000;

// "x4" / "a1": a letter and a number.
bool is_value_name(const std::string& name, char letter)
{
  return name.size() >= 2 && name[0] == letter &&
         std::all_of(name.begin() + 1, name.end(), [](unsigned char c) { return std::isdigit(c); });
}
}

CoordinatePanel::CoordinatePanel(QWidget* parent)
  : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  auto* object_row = new QHBoxLayout;
  object_row->addWidget(new QLabel(tr("Object:"), this));
  objects_ = new QComboBox(this);
  objects_->setObjectName("objectPicker");
  object_row->addWidget(objects_, 1);
  layout->addLayout(object_row);

  coordinate_box_ = new QGroupBox(tr("Cross-section (x4 ...)"), this);
  coordinate_form_ = new QFormLayout(coordinate_box_);
  layout->addWidget(coordinate_box_);
  parameter_box_ = new QGroupBox(tr("Parameters a[]"), this);
  parameter_form_ = new QFormLayout(parameter_box_);
  layout->addWidget(parameter_box_);
  layout->addStretch(1);

  connect(objects_, qOverload<int>(&QComboBox::currentIndexChanged), this,
    [this] { emit objectChanged(); });
}

void CoordinatePanel::setObjects(const std::vector<std::string>& names, int fallback)
{
  const std::string current = currentObject();
  QSignalBlocker block(objects_);
  objects_->clear();
  int selected = -1;
  for (int i = 0; i < static_cast<int>(names.size()); ++i)
  {
    objects_->addItem(QString::fromStdString(names[i]));
    if (names[i] == current)
      selected = i;
  }
  if (selected < 0)
    selected = fallback;
  objects_->setCurrentIndex(selected);
}

std::string CoordinatePanel::currentObject() const
{
  return objects_->currentText().toStdString();
}

bool CoordinatePanel::selectObject(const std::string& name)
{
  const int index = objects_->findText(QString::fromStdString(name), Qt::MatchFixedString);
  if (index < 0)
    return false;
  objects_->setCurrentIndex(index);
  return true;
}

void CoordinatePanel::clearForm(QFormLayout* form)
{
  while (form->rowCount() > 0)
    form->removeRow(0);
}

double CoordinatePanel::remembered(const std::string& name, double fallback) const
{
  const auto found = values_.find(name);
  return found != values_.end() ? found->second : fallback;
}

void CoordinatePanel::setModelShape(int x_dim, int a_dim, const CoordinateRanges& ranges)
{
  clearForm(coordinate_form_);
  clearForm(parameter_form_);
  sliders_.clear();
  parameters_.clear();

  for (int i = 3; i < x_dim; ++i)
  {
    Coordinate coordinate;
    coordinate.name = "x" + std::to_string(i + 1);
    const auto range = ranges.range(i);
    coordinate.lo = range[0];
    coordinate.hi = range[1];
    const double value = std::clamp(remembered(coordinate.name, range[0]), range[0], range[1]);

    addCoordinateRow(coordinate, value);
  }
  coordinate_box_->setVisible(!sliders_.empty());

  for (int i = 0; i < a_dim; ++i)
  {
    const std::string name = "a" + std::to_string(i + 1);
    auto* spin = new QDoubleSpinBox(parameter_box_);
    spin->setObjectName(QString::fromStdString(name) + "Spin");
    spin->setDecimals(4);
    spin->setRange(-1e6, 1e6);
    spin->setValue(remembered(name, 0.0));
    connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, name](double v) {
      values_[name] = v;
      emit valuesChanged();
    });
    parameter_form_->addRow(QString::fromStdString(name), spin);
    parameters_.push_back(spin);
  }
  parameter_box_->setVisible(!parameters_.empty());
}

// One coordinate's row: its slider and spin box, which show one value (each updates the other
// without echo), and its projected box, which disables both while ticked.
void CoordinatePanel::addCoordinateRow(Coordinate coordinate, double value)
{
  const std::array<double, 2> range{ coordinate.lo, coordinate.hi };
  auto* row = new QWidget(coordinate_box_);
  auto* row_layout = new QHBoxLayout(row);
  row_layout->setContentsMargins(0, 0, 0, 0);
  coordinate.slider = new QSlider(Qt::Horizontal, row);
  coordinate.slider->setObjectName(QString::fromStdString(coordinate.name) + "Slider");
  coordinate.slider->setRange(0, kSliderSteps);
  coordinate.spin = new QDoubleSpinBox(row);
  coordinate.spin->setObjectName(QString::fromStdString(coordinate.name) + "Spin");
  coordinate.spin->setDecimals(3);
  coordinate.spin->setRange(range[0], range[1]);
  coordinate.spin->setSingleStep((range[1] - range[0]) / 100);
  coordinate.spin->setValue(value);
  coordinate.slider->setValue(
    static_cast<int>(std::lround((value - range[0]) / (range[1] - range[0]) * kSliderSteps)));
  coordinate.projected = new QCheckBox(tr("projected"), row);
  coordinate.projected->setObjectName(QString::fromStdString(coordinate.name) + "Projected");
  coordinate.projected->setToolTip(tr("Show the union over the slider's whole range (the model "
                                      "projected along this coordinate) instead of one value"));
  const bool projected = projected_.count(coordinate.name) != 0;
  coordinate.projected->setChecked(projected);
  coordinate.slider->setEnabled(!projected);
  coordinate.spin->setEnabled(!projected);
  row_layout->addWidget(coordinate.slider, 1);
  row_layout->addWidget(coordinate.spin);
  row_layout->addWidget(coordinate.projected);
  coordinate_form_->addRow(QString::fromStdString(coordinate.name), row);

  const std::size_t k = sliders_.size();
  connect(coordinate.slider, &QSlider::valueChanged, this, [this, k](int step) {
    Coordinate& c = sliders_[k];
    const double v = c.lo + (c.hi - c.lo) * step / kSliderSteps;
    {
      QSignalBlocker block(c.spin);
      c.spin->setValue(v);
    }
    values_[c.name] = v;
    emit valuesChanged();
  });
  connect(coordinate.spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
    [this, k](double v) {
      Coordinate& c = sliders_[k];
      {
        QSignalBlocker block(c.slider);
        c.slider->setValue(
          static_cast<int>(std::lround((v - c.lo) / (c.hi - c.lo) * kSliderSteps)));
      }
      values_[c.name] = v;
      emit valuesChanged();
    });
  connect(coordinate.projected, &QCheckBox::toggled, this, [this, k](bool on) {
    Coordinate& c = sliders_[k];
    c.slider->setEnabled(!on);
    c.spin->setEnabled(!on);
    if (on)
      projected_.insert(c.name);
    else
      projected_.erase(c.name);
    emit valuesChanged();
  });
  values_[coordinate.name] = value;
  sliders_.push_back(coordinate);
}

std::vector<double> CoordinatePanel::fixedValues() const
{
  std::vector<double> values;
  for (const Coordinate& c : sliders_)
    values.push_back(c.spin->value());
  return values;
}

std::vector<frep::project::CoordinateRange> CoordinatePanel::projectedRanges() const
{
  std::vector<frep::project::CoordinateRange> ranges;
  for (std::size_t k = 0; k < sliders_.size(); ++k)
    if (sliders_[k].projected->isChecked())
      ranges.push_back({ static_cast<int>(k) + 4, sliders_[k].lo, sliders_[k].hi });
  return ranges;
}

std::vector<double> CoordinatePanel::parameters() const
{
  std::vector<double> values;
  for (const QDoubleSpinBox* spin : parameters_)
    values.push_back(spin->value());
  return values;
}

bool CoordinatePanel::setValue(const std::string& raw_name, double value)
{
  const std::string name = frep::lower_case(raw_name);
  if (!is_value_name(name, 'x') && !is_value_name(name, 'a'))
    return false;
  values_[name] = value;
  const int index = std::stoi(name.substr(1)) - 1;
  if (name[0] == 'x' && index >= 3 && index - 3 < static_cast<int>(sliders_.size()))
    sliders_[index - 3].spin->setValue(value); // emits valuesChanged through the spin box
  else if (name[0] == 'a' && index >= 0 && index < static_cast<int>(parameters_.size()))
    parameters_[index]->setValue(value);
  return true;
}

bool CoordinatePanel::setProjected(const std::string& raw_name, bool projected)
{
  const std::string name = frep::lower_case(raw_name);
  if (!is_value_name(name, 'x'))
    return false;
  const int index = std::stoi(name.substr(1)) - 1;
  if (index >= 3 && index - 3 < static_cast<int>(sliders_.size()))
    sliders_[index - 3].projected->setChecked(projected); // emits valuesChanged when it changes
  else if (projected)
    projected_.insert(name);
  else
    projected_.erase(name);
  return true;
}

QSlider* CoordinatePanel::slider(int index) const
{
  const int k = index - 3;
  return k >= 0 && k < static_cast<int>(sliders_.size()) ? sliders_[k].slider : nullptr;
}

} // namespace frepstudio
