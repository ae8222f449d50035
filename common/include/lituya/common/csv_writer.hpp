#pragma once
// The one way Lituya writes a CSV table (post tables, sweep.csv, the verification tables), so
// that every table follows RFC 4180 the same way:
// - a field holding a comma, a double quote, a CR or an LF is enclosed in double quotes, and a
//   double quote inside it is doubled ("a ""b""", c); other fields are written as they are, so
//   numeric tables stay plain for gnuplot, awk and a quick look;
// - records end with LF, not the RFC's CRLF. The RFC describes the MIME type; the programs that
//   read these tables (gnuplot, Lituya's own readers, Python's csv and pandas, R, spreadsheets,
//   grep and awk) all take LF, while a stray CR would end up inside the last field of a reader
//   that splits on LF. A line break inside a quoted field is written as it is;
// - numbers are written in the shortest form that reads back to the same double (std::to_chars),
//   so no digit of a result is lost and none is invented; NaN and infinities are an empty field
//   ("no value", as in the reference tables Lituya reads);
// - the first record is the header; every record has as many fields as the header.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lituya {

// `text` as one CSV field: as it is, or quoted as above.
std::string csv_field(std::string_view text);

// `value` in the shortest text that parses back to it exactly; "" when it is not finite.
std::string csv_number(double value);

// The fields of one CSV record, undoing csv_field (quotes removed, "" turned into "). A record
// whose quoted field spans lines must be given whole. A trailing CR is dropped, so a table
// written with CRLF reads the same.
std::vector<std::string> csv_split(std::string_view record);

// A table gathered in memory and written whole, atomically (atomic_file.hpp): a full disk
// leaves the earlier table or none, never a torn one.
class CsvWriter {
 public:
  explicit CsvWriter(const std::vector<std::string>& header);

  // Fields of the current record, left to right.
  CsvWriter& text(std::string_view value);
  CsvWriter& number(double value);
  CsvWriter& integer(std::int64_t value);
  // Ends the current record. Throws std::logic_error when it does not have as many fields as
  // the header (a programming error that would shift every later column).
  void end_row();
  // A whole record of numbers.
  void row(const std::vector<double>& values);

  // The table so far (complete records only).
  const std::string& str() const { return text_; }
  // Writes the table to `file` atomically; throws WriteError (atomic_file.hpp).
  void write(const std::filesystem::path& file) const;

 private:
  void field(const std::string& value);

  std::size_t columns_;
  std::size_t fields_ = 0;  // in the current record
  std::string text_;
  std::string record_;
};

}  // namespace lituya
