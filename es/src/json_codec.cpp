#include "json_codec.hpp"

#include <cmath>

#include "motoflex_es/checkpoint.hpp"

namespace motoflex_es::detail {

void fail_state(const std::string& message) {
  throw CheckpointError("strategy state: " + message);
}

nlohmann::json double_to_json(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

nlohmann::json vector_to_json(const std::vector<double>& values) {
  nlohmann::json array = nlohmann::json::array();
  for (double value : values) array.push_back(double_to_json(value));
  return array;
}

const nlohmann::json& member(const nlohmann::json& object, const std::string& field) {
  if (!object.is_object()) fail_state("expected an object holding '" + field + "'");
  const auto found = object.find(field);
  if (found == object.end()) fail_state("missing field '" + field + "'");
  return *found;
}

double double_from_json(const nlohmann::json& value, const std::string& field) {
  if (value.is_number()) return value.get<double>();
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
  }
  fail_state(field + ": expected a number, \"inf\", \"-inf\" or \"nan\", found " + value.dump());
}

std::vector<double> vector_from_json(const nlohmann::json& value, const std::string& field,
                                     std::size_t expected_size) {
  if (!value.is_array()) fail_state(field + ": expected an array");
  if (expected_size != kAnySize && value.size() != expected_size) {
    fail_state(field + ": expected " + std::to_string(expected_size) + " values, found " +
               std::to_string(value.size()));
  }
  std::vector<double> values;
  values.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    values.push_back(double_from_json(value[i], field + "[" + std::to_string(i) + "]"));
  }
  return values;
}

std::uint64_t uint_from_json(const nlohmann::json& value, const std::string& field) {
  // Integers are written as JSON integers; a float here means the file was edited or damaged.
  if (!value.is_number_unsigned()) {
    fail_state(field + ": expected a nonnegative integer, found " + value.dump());
  }
  return value.get<std::uint64_t>();
}

std::string string_from_json(const nlohmann::json& value, const std::string& field) {
  if (!value.is_string()) fail_state(field + ": expected a string, found " + value.dump());
  return value.get<std::string>();
}

void check_same_options(const nlohmann::json& saved, const nlohmann::json& expected) {
  for (const auto& [key, value] : expected.items()) {
    const nlohmann::json& found = member(saved, key);
    if (found != value) {
      fail_state("saved with " + key + " = " + found.dump() + ", this run has " + key + " = " +
                 value.dump());
    }
  }
}

nlohmann::json matrix_to_json(const Eigen::MatrixXd& matrix) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    std::vector<double> row(static_cast<std::size_t>(matrix.cols()));
    for (Eigen::Index c = 0; c < matrix.cols(); ++c)
      row[static_cast<std::size_t>(c)] = matrix(r, c);
    rows.push_back(vector_to_json(row));
  }
  return rows;
}

Eigen::MatrixXd matrix_from_json(const nlohmann::json& rows, const std::string& field,
                                 std::size_t n) {
  if (!rows.is_array() || rows.size() != n) {
    fail_state(field + ": expected " + std::to_string(n) + " rows");
  }
  Eigen::MatrixXd matrix(n, n);
  for (std::size_t r = 0; r < n; ++r) {
    const std::vector<double> row =
        vector_from_json(rows[r], field + "[" + std::to_string(r) + "]", n);
    for (std::size_t c = 0; c < n; ++c) {
      matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row[c];
    }
  }
  return matrix;
}

nlohmann::json eigen_vector_to_json(const Eigen::VectorXd& v) {
  return vector_to_json(std::vector<double>(v.data(), v.data() + v.size()));
}

Eigen::VectorXd eigen_vector_from_json(const nlohmann::json& value, const std::string& field,
                                       std::size_t n) {
  const std::vector<double> values = vector_from_json(value, field, n);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(n));
}

}  // namespace motoflex_es::detail
