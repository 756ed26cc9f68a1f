#pragma once
// Errors of the meshing stages name the input they came from: "far.pqr: the grid of ...
// would need 22 GB ..." tells a user running several inputs which one to look at. Errors
// that already say what they are about pass through unchanged: a reader's (file and
// line), an option's, an output's.
#include <string>
#include <utility>

#include "molmesh/core/error.hpp"

namespace molmesh::cli {

template <class Work>
decltype(auto) naming_input(const std::string& input, Work&& work) {
  try {
    return std::forward<Work>(work)();
  } catch (const InputError&) {
    throw;
  } catch (const OptionError&) {
    throw;
  } catch (const OutputError&) {
    throw;
  } catch (const Error& e) {
    throw Error(input + ": " + e.what());
  }
}

}  // namespace molmesh::cli
