#include "Shapes/shape_functions.h"

#include <cmath>

namespace frep::shapes
{
namespace
{

UserFunction point_of_x(const std::string& name)
{
  UserFunction f;
  f.name = name;
  f.kinds = { ArgKind::Array };
  f.array_sizes = { 3 };
  return f;
}

std::array<double, 3> at(std::span<const UserArgument> args)
{
  return { args[0].values[0], args[0].values[1], args[0].values[2] };
}

template<class Shape>
void add_forms(UserFunction& f, std::shared_ptr<const Shape> shape)
{
  f.point = [shape](std::span<const UserArgument> args, double& v)
  {
    v = shape->value(at(args));
    return std::isfinite(v);
  };
  f.interval = [shape](std::span<const UserIntervalArgument> args, double& lo, double& hi,
                 bool& fails)
  {
    const std::array<double, 3> l{ args[0].lo[0], args[0].lo[1], args[0].lo[2] };
    const std::array<double, 3> h{ args[0].hi[0], args[0].hi[1], args[0].hi[2] };
    fails = false;
    return shape->enclose(l, h, lo, hi);
  };
  f.gradient = [shape](std::span<const UserArgument> args, double& v, std::span<double> g)
  {
    std::array<double, 3> d{};
    v = shape->value_and_gradient(at(args), d);
    g[0] = d[0];
    g[1] = d[1];
    g[2] = d[2];
    return std::isfinite(v);
  };
}

} // namespace

UserFunction mesh_function(const std::string& name, std::shared_ptr<const MeshDistance> mesh)
{
  UserFunction f = point_of_x(name);
  add_forms(f, std::move(mesh));
  return f;
}

UserFunction volume_function(const std::string& name, std::shared_ptr<const VolumeField> volume)
{
  UserFunction f = point_of_x(name);
  add_forms(f, std::move(volume));
  return f;
}

UserFunction point_function(const std::string& name,
  std::function<double(const std::array<double, 3>&)> fn)
{
  UserFunction f = point_of_x(name);
  f.point = [fn = std::move(fn)](std::span<const UserArgument> args, double& v)
  {
    v = fn(at(args));
    return !std::isnan(v);
  };
  return f;
}

std::string wrapper_program(const std::string& name)
{
  // The object is not called `name` itself: inside its own body that would be an object name.
  const std::string object = name + "_model";
  return object + "(x[3], a[1])\n{\n  " + object + " = " + name + "(x);\n}\n";
}

} // namespace frep::shapes
