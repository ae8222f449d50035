#pragma once
// Machine-readable summaries (the verification report's summary.json, a sweep's sweep.json)
// are built as nlohmann::json values and written here, so that every one escapes strings
// properly and keeps every double exactly: nlohmann writes the shortest text that reads back
// to the same double, where a hand-built stream kept 4 or 6 digits. NaN and infinities, which
// JSON cannot hold, become null.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace lituya {

// A JSON value whose objects keep their keys in the order they were set (nlohmann::json sorts
// them): a summary reads in the order it was built, e.g. a sweep's keys in the sweep's order.
using Json = nlohmann::ordered_json;

// `value` as text, indented by 2, ending with a newline.
std::string json_text(const Json& value);

// Writes json_text(value) to `file` atomically (atomic_file.hpp); throws WriteError.
void write_json_file(const std::filesystem::path& file, const Json& value);

// `value`, or null when it is not finite. nlohmann writes a non-finite double as null too, but
// saying so where the value is set keeps the intent visible and the type checkable.
Json json_number(double value);

}  // namespace lituya
