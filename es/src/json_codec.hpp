#pragma once

// Exact JSON encoding of strategy state (internal to the es library).

#include <Eigen/Dense>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace motoflex_es::detail {

inline constexpr std::size_t kAnySize = std::numeric_limits<std::size_t>::max();

// Finite doubles become JSON numbers (nlohmann writes the shortest text that reads back to the
// same bits); +inf, -inf and NaN, which JSON cannot hold, become the strings "inf", "-inf" and
// "nan" (nlohmann would silently write null).
nlohmann::json double_to_json(double value);
nlohmann::json vector_to_json(const std::vector<double>& values);

// The readers throw CheckpointError("strategy state: <field>: <what is wrong>").
const nlohmann::json& member(const nlohmann::json& object, const std::string& field);
double double_from_json(const nlohmann::json& value, const std::string& field);
std::vector<double> vector_from_json(const nlohmann::json& value, const std::string& field,
                                     std::size_t expected_size);
std::uint64_t uint_from_json(const nlohmann::json& value, const std::string& field);
std::string string_from_json(const nlohmann::json& value, const std::string& field);
[[noreturn]] void fail_state(const std::string& message);

// Square matrices as an array of rows, vectors as arrays, with the same exactness.
nlohmann::json matrix_to_json(const Eigen::MatrixXd& matrix);
Eigen::MatrixXd matrix_from_json(const nlohmann::json& rows, const std::string& field,
                                 std::size_t n);
nlohmann::json eigen_vector_to_json(const Eigen::VectorXd& v);
Eigen::VectorXd eigen_vector_from_json(const nlohmann::json& value, const std::string& field,
                                       std::size_t n);

// Throws CheckpointError naming the first entry of `expected` that differs in `saved`: the saved
// state belongs to a run with other options.
void check_same_options(const nlohmann::json& saved, const nlohmann::json& expected);

}  // namespace motoflex_es::detail
