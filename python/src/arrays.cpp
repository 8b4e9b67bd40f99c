#include "arrays.hpp"

#include <stdexcept>
#include <string>

namespace grainlab::python {
namespace {

DoubleArray doubles(const py::dict& columns, const char* name) {
  if (!columns.contains(name)) throw std::invalid_argument(std::string("contacts: missing column ") + name);
  return DoubleArray::ensure(columns[name]);
}

}  // namespace

std::vector<ContactRecord> contactsFromColumns(const py::dict& columns) {
  if (!columns.contains("i") || !columns.contains("j"))
    throw std::invalid_argument("contacts: missing column i or j");
  const IndexArray i = IndexArray::ensure(columns["i"]);
  const IndexArray j = IndexArray::ensure(columns["j"]);
  const char* names[] = {"px", "py", "nx", "ny", "fn", "ft"};
  DoubleArray v[6];
  for (int k = 0; k < 6; ++k) v[k] = doubles(columns, names[k]);
  const py::ssize_t n = i.size();
  if (i.ndim() != 1) throw std::invalid_argument("contacts: column i must be one-dimensional");
  if (j.size() != n) throw std::invalid_argument("contacts: column j has " + std::to_string(j.size()) +
                                                 " entries, i has " + std::to_string(n));
  for (int k = 0; k < 6; ++k) {
    if (!v[k] || v[k].size() != n)
      throw std::invalid_argument(std::string("contacts: column ") + names[k] + " has " +
                                  std::to_string(v[k] ? v[k].size() : 0) + " entries, i has " + std::to_string(n));
  }
  std::vector<ContactRecord> out(static_cast<size_t>(n));
  for (py::ssize_t c = 0; c < n; ++c) {
    ContactRecord& r = out[static_cast<size_t>(c)];
    r.i = static_cast<int>(i.at(c));
    r.j = static_cast<int>(j.at(c));
    r.point = Vec2(v[0].at(c), v[1].at(c));
    r.normal = Vec2(v[2].at(c), v[3].at(c));
    r.fn = v[4].at(c);
    r.ft = v[5].at(c);
  }
  return out;
}

std::vector<Vec2> centroidsFromArray(const DoubleArray& xy) {
  if (xy.ndim() != 2 || xy.shape(1) != 2)
    throw std::invalid_argument("centroids: expected an (n, 2) array of x, y");
  std::vector<Vec2> out(static_cast<size_t>(xy.shape(0)));
  for (py::ssize_t k = 0; k < xy.shape(0); ++k) out[static_cast<size_t>(k)] = Vec2(xy.at(k, 0), xy.at(k, 1));
  return out;
}

std::vector<unsigned char> flagsFromArray(const FlagArray& flags) {
  if (flags.ndim() != 1) throw std::invalid_argument("inside: expected a one-dimensional array");
  return std::vector<unsigned char>(flags.data(), flags.data() + flags.size());
}

}  // namespace grainlab::python
