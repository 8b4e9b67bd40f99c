#pragma once
// Between numpy and the engine's types: contact arrays in, column dictionaries out. The
// column names are those of contacts_final.csv and particles_final.csv (contracts.md).
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"

namespace grainlab::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<long long, py::array::c_style | py::array::forcecast>;
using FlagArray = py::array_t<unsigned char, py::array::c_style | py::array::forcecast>;

/// Contacts from one array per column of contacts_final.csv (i, j, px, py, nx, ny, fn, ft);
/// throws std::invalid_argument naming a column whose length differs from i's.
std::vector<ContactRecord> contactsFromColumns(const py::dict& columns);
/// Particle centroids from an (n, 2) array; throws std::invalid_argument for another shape.
std::vector<Vec2> centroidsFromArray(const DoubleArray& xy);
/// The inside flags (n entries, non-zero = part of the specimen).
std::vector<unsigned char> flagsFromArray(const FlagArray& flags);

/// A column as a new numpy array.
template <class T>
py::array_t<T> column(const std::vector<T>& values) {
  py::array_t<T> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace grainlab::python
