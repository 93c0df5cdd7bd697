#pragma once

// Copies of motoflex's frame-major vectors as NumPy arrays (the arrays own their data, so they
// outlive the result they came from).

#include <pybind11/numpy.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace motoflex::python {

// A (size,) array.
inline pybind11::array_t<double> vector_array(const std::vector<double>& values) {
  pybind11::array_t<double> array(static_cast<pybind11::ssize_t>(values.size()));
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = values[i];
  return array;
}

// A (rows, columns) array of the first rows * columns values (frame-major storage).
inline pybind11::array_t<double> matrix_array(const std::vector<double>& values, std::size_t rows,
                                              std::size_t columns) {
  if (values.size() < rows * columns) throw std::logic_error("matrix_array: too few values");
  pybind11::array_t<double> array(
      {static_cast<pybind11::ssize_t>(rows), static_cast<pybind11::ssize_t>(columns)});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < rows * columns; ++i) out[i] = values[i];
  return array;
}

// The values of a 1-D or 2-D array, row-major; throws ValueError for other shapes.
inline std::vector<double> array_values(
    const pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>& array,
    std::size_t expected_columns, const char* what) {
  if (array.ndim() == 2 && static_cast<std::size_t>(array.shape(1)) != expected_columns) {
    throw pybind11::value_error(std::string(what) + ": expected " +
                                std::to_string(expected_columns) + " columns");
  }
  if (array.ndim() != 1 && array.ndim() != 2) {
    throw pybind11::value_error(std::string(what) + ": expected a 1-D or 2-D array");
  }
  return std::vector<double>(array.data(), array.data() + array.size());
}

}  // namespace motoflex::python
