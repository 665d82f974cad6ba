#include "user_library.h"

#include "frepkit_user.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <memory>
#include <vector>

namespace frep
{
namespace
{

// Arguments flattened for a C callback: on the stack for the usual few items.
class Flat
{
public:
  explicit Flat(std::size_t n)
  {
    if (n > small_.size())
    {
      large_.resize(n);
    }
  }
  double* data() { return large_.empty() ? small_.data() : large_.data(); }

private:
  std::array<double, 64> small_{};
  std::vector<double> large_;
};

struct Registration
{
  std::string library;
  std::shared_ptr<void> handle;
  UserFunctionRegistry staged;
  std::string error;
  std::vector<std::string> added;
};

// A C function description as a UserFunction; `handle` keeps the library loaded.
UserFunction wrap(const frepkit_user_function& c, std::shared_ptr<void> handle)
{
  UserFunction f;
  f.name = c.name;
  for (int i = 0; i < c.argc; ++i)
  {
    f.kinds.push_back(c.kinds[i] == FREPKIT_ARG_ARRAY ? ArgKind::Array : ArgKind::Real);
    if (c.array_sizes)
    {
      f.array_sizes.push_back(c.kinds[i] == FREPKIT_ARG_ARRAY ? c.array_sizes[i] : 0);
    }
  }
  const frepkit_point_fn point = c.point;
  const frepkit_interval_fn interval = c.interval;
  const frepkit_gradient_fn gradient = c.gradient;
  void* user = c.user;
  f.point = [point, user, handle](std::span<const UserArgument> args, double& value)
  {
    std::array<int, kMaxFunctionArity> sizes{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < args.size(); ++i)
    {
      sizes[i] = args[i].size;
      n += static_cast<std::size_t>(args[i].size);
    }
    Flat flat(n);
    double* p = flat.data();
    for (const UserArgument& a : args)
    {
      p = std::copy_n(a.values, a.size, p);
    }
    return point(user, flat.data(), sizes.data(), static_cast<int>(args.size()), &value) == 0;
  };
  if (interval)
  {
    f.interval = [interval, user, handle](
                   std::span<const UserIntervalArgument> args, double& lo, double& hi, bool& may_fail)
    {
      std::array<int, kMaxFunctionArity> sizes{};
      std::size_t n = 0;
      for (std::size_t i = 0; i < args.size(); ++i)
      {
        sizes[i] = args[i].size;
        n += static_cast<std::size_t>(args[i].size);
      }
      Flat flo(n);
      Flat fhi(n);
      double* l = flo.data();
      double* h = fhi.data();
      for (const UserIntervalArgument& a : args)
      {
        l = std::copy_n(a.lo, a.size, l);
        h = std::copy_n(a.hi, a.size, h);
      }
      int fails = 0;
      const int status = interval(user, flo.data(), fhi.data(), sizes.data(),
        static_cast<int>(args.size()), &lo, &hi, &fails);
      may_fail = fails != 0;
      return status == 0;
    };
  }
  if (gradient)
  {
    f.gradient = [gradient, user, handle](
                   std::span<const UserArgument> args, double& value, std::span<double> g)
    {
      std::array<int, kMaxFunctionArity> sizes{};
      std::size_t n = 0;
      for (std::size_t i = 0; i < args.size(); ++i)
      {
        sizes[i] = args[i].size;
        n += static_cast<std::size_t>(args[i].size);
      }
      if (g.size() < n)
      {
        return false;
      }
      Flat flat(n);
      double* p = flat.data();
      for (const UserArgument& a : args)
      {
        p = std::copy_n(a.values, a.size, p);
      }
      return gradient(user, flat.data(), sizes.data(), static_cast<int>(args.size()), &value,
               g.data()) == 0;
    };
  }
  return f;
}

extern "C" int frepkit_add_function(void* context, const frepkit_user_function* c)
{
  auto* r = static_cast<Registration*>(context);
  const auto refuse = [&](const std::string& why)
  {
    if (r->error.empty())
    {
      r->error = why;
    }
    return 1;
  };
  if (c == nullptr)
  {
    return refuse("a null function description");
  }
  const std::string name = c->name ? c->name : "";
  if (name.empty())
  {
    return refuse("a function without a name");
  }
  if (c->argc < 0 || c->argc > kMaxFunctionArity)
  {
    return refuse("function '" + name + "': bad arity " + std::to_string(c->argc) +
      " (0 to " + std::to_string(kMaxFunctionArity) + " arguments)");
  }
  if (c->argc > 0 && c->kinds == nullptr)
  {
    return refuse("function '" + name + "': no argument kinds");
  }
  for (int i = 0; i < c->argc; ++i)
  {
    if (c->kinds[i] != FREPKIT_ARG_REAL && c->kinds[i] != FREPKIT_ARG_ARRAY)
    {
      return refuse("function '" + name + "': argument " + std::to_string(i + 1) +
        " has the unknown kind " + std::to_string(c->kinds[i]));
    }
  }
  if (c->point == nullptr)
  {
    return refuse("function '" + name + "' has no point form");
  }
  if (std::string e = r->staged.add(wrap(*c, r->handle)); !e.empty())
  {
    return refuse(e);
  }
  r->added.push_back(name);
  return 0;
}

} // namespace

UserLibraryResult load_user_library(const std::string& path, UserFunctionRegistry& registry)
{
  UserLibraryResult result;
  const std::string label = "user library " + path;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    result.error = label + ": no such file";
    return result;
  }
  // A name without a slash would make dlopen search the system paths: the user means a file.
  const std::string open_path =
    path.find('/') == std::string::npos ? "./" + path : path;
  void* raw = dlopen(open_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (raw == nullptr)
  {
    const char* why = dlerror();
    result.error = label + ": cannot be loaded: " + (why ? why : "unknown reason");
    return result;
  }
  Registration r;
  r.library = path;
  r.handle = std::shared_ptr<void>(raw, [](void* h) { dlclose(h); });
  dlerror();
  void* entry = dlsym(raw, FREPKIT_USER_ENTRY);
  if (entry == nullptr)
  {
    result.error = label + ": has no entry point " FREPKIT_USER_ENTRY " (see frepkit_user.h)";
    return result;
  }
  frepkit_user_api api{ FREPKIT_USER_ABI_VERSION, &r, &frepkit_add_function };
  const auto fn = reinterpret_cast<frepkit_user_register_fn>(entry);
  const int status = fn(&api);
  if (!r.error.empty())
  {
    result.error = label + ": " + r.error;
    return result;
  }
  if (status != 0)
  {
    result.error = label + ": " FREPKIT_USER_ENTRY " failed with status " + std::to_string(status);
    return result;
  }
  // Clashes with functions already in the registry (another library): checked before adding
  // anything, so a failed load leaves the registry as it was.
  UserFunctionRegistry merged = registry;
  if (std::string e = merged.merge(r.staged); !e.empty())
  {
    result.error = label + ": " + e;
    return result;
  }
  registry = std::move(merged);
  result.added = std::move(r.added);
  return result;
}

} // namespace frep
