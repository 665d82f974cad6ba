// What the projection tests share: a model compiled from HyperFun text.
#pragma once

#include "Compiler/load_model.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace frep::project::test
{

inline std::shared_ptr<const Model> model_of(const std::string& text)
{
  const LoadedModel loaded = load_model(ModelSource::from_text(text));
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.model;
}

} // namespace frep::project::test
