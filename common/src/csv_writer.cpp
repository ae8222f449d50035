#include "lituya/common/csv_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "lituya/common/atomic_file.hpp"

namespace lituya {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::string csv_number(double value) {
  if (!std::isfinite(value)) return "";
  // The shortest representation that round-trips (guaranteed by to_chars without a
  // precision); 32 characters hold any double in it.
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::vector<std::string> csv_split(std::string_view record) {
  if (!record.empty() && record.back() == '\r') record.remove_suffix(1);
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < record.size(); ++i) {
    const char c = record[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < record.size() && record[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

CsvWriter::CsvWriter(const std::vector<std::string>& header) : columns_(header.size()) {
  for (const std::string& name : header) text(name);
  end_row();
}

void CsvWriter::field(const std::string& value) {
  if (fields_ > 0) record_ += ',';
  record_ += value;
  ++fields_;
}

CsvWriter& CsvWriter::text(std::string_view value) {
  field(csv_field(value));
  return *this;
}

CsvWriter& CsvWriter::number(double value) {
  field(csv_number(value));
  return *this;
}

CsvWriter& CsvWriter::integer(std::int64_t value) {
  field(std::to_string(value));
  return *this;
}

void CsvWriter::end_row() {
  if (fields_ != columns_)
    throw std::logic_error("CSV record with " + std::to_string(fields_) +
                           " fields under a header of " + std::to_string(columns_));
  text_ += record_;
  text_ += '\n';
  record_.clear();
  fields_ = 0;
}

void CsvWriter::row(const std::vector<double>& values) {
  for (double v : values) number(v);
  end_row();
}

void CsvWriter::write(const std::filesystem::path& file) const {
  write_file_atomically(file, text_);
}

}  // namespace lituya
