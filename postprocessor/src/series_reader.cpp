// Reading the solver's output series: the .pvd collection (times and files) and the point
// files it lists (solid points and liquid points alike).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "lituya/common/input_error.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

std::string xml_unescaped(std::string_view text) {
  static const std::pair<std::string_view, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (size_t i = 0; i < text.size();) {
    bool replaced = false;
    if (text[i] == '&') {
      for (const auto& [entity, c] : entities) {
        if (text.substr(i, entity.size()) == entity) {
          out += c;
          i += entity.size();
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

// The value of attribute `name` in the text of one XML start tag, if present.
std::optional<std::string> attribute(std::string_view tag, std::string_view name) {
  for (size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    // Must be a whole attribute name: preceded by white space, followed by '='.
    if (at == 0 || !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
    size_t p = at + name.size();
    while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
    if (p >= tag.size() || tag[p] != '=') continue;
    ++p;
    while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) return std::nullopt;
    size_t close = tag.find(tag[p], p + 1);
    if (close == std::string_view::npos) return std::nullopt;
    return xml_unescaped(tag.substr(p + 1, close - p - 1));
  }
  return std::nullopt;
}

// VTK reports reader errors as events; catching them turns a corrupt file into an InputError
// that names it, instead of a message on stderr and an empty grid.
class ErrorCatcher : public vtkCommand {
 public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* call_data) override {
    if (!message.empty() || !call_data) return;
    // VTK's text is "ERROR: In <source file>, line N\n<class> (<address>): <what>"; only
    // <what> means something to a user.
    std::string text = static_cast<const char*>(call_data);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    const size_t last_line = text.rfind('\n');
    if (last_line != std::string::npos) text = text.substr(last_line + 1);
    const size_t what = text.find("): ");
    message = what == std::string::npos ? text : text.substr(what + 3);
  }
  std::string message;
};

}  // namespace

std::vector<SeriesEntry> read_pvd(const fs::path& pvd) {
  std::ifstream in(pvd);
  if (!in)
    throw InputError(pvd.string(), 0,
                     "cannot open the output series (has `lituya solve` written it?)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  auto line_at = [&](size_t pos) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + pos, '\n'));
  };

  size_t root = text.find("<VTKFile");
  if (root == std::string::npos || text.find("<Collection") == std::string::npos ||
      attribute(std::string_view(text).substr(root, text.find('>', root) - root), "type") !=
          "Collection")
    throw InputError(pvd.string(), 1,
                     "not a VTK .pvd collection (no <VTKFile type=\"Collection\">)");
  if (text.find("</Collection>") == std::string::npos ||
      text.find("</VTKFile>") == std::string::npos)
    throw InputError(pvd.string(), line_at(text.size()),
                     "the collection is incomplete (no closing </Collection> or </VTKFile>)");

  std::vector<SeriesEntry> entries;
  for (size_t at = text.find("<DataSet"); at != std::string::npos;
       at = text.find("<DataSet", at + 1)) {
    const int line = line_at(at);
    size_t end = text.find('>', at);
    if (end == std::string::npos)
      throw InputError(pvd.string(), line, "unterminated <DataSet> element");
    std::string_view tag = std::string_view(text).substr(at, end - at);

    auto timestep = attribute(tag, "timestep");
    double time = 0;
    if (!timestep) throw InputError(pvd.string(), line, "<DataSet> without a timestep attribute");
    auto [ptr, ec] = std::from_chars(timestep->data(), timestep->data() + timestep->size(), time);
    if (ec != std::errc() || ptr != timestep->data() + timestep->size())
      throw InputError(pvd.string(), line, "timestep \"" + *timestep + "\" is not a number");

    auto file = attribute(tag, "file");
    if (!file || file->empty())
      throw InputError(pvd.string(), line, "<DataSet> without a file attribute");
    fs::path dataset(*file);
    if (dataset.is_relative()) dataset = pvd.parent_path() / dataset;
    entries.push_back({time, dataset});
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const SeriesEntry& a, const SeriesEntry& b) { return a.time < b.time; });
  return entries;
}

namespace {

// Solid and liquid point files share the reader; only liquid points carry a meaningful
// porosity (that of the mixture they are water of).
PointCloud read_cloud(const fs::path& vtu, int dimension, bool liquid) {
  if (!fs::is_regular_file(vtu))
    throw InputError(vtu.string(), 0, "point output file is missing (listed in the .pvd?)");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  vtkNew<ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetReaderErrorObserver(errors);
  reader->SetParserErrorObserver(errors);
  if (!reader->CanReadFile(vtu.c_str()))
    throw InputError(vtu.string(), 0, "not a VTK XML unstructured grid (.vtu) file");
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (!errors->message.empty() || reader->GetErrorCode() != 0 || !grid)
    throw InputError(vtu.string(), 0,
                     "cannot read the points (truncated or corrupt file?)" +
                         (errors->message.empty() ? std::string() : ": " + errors->message));

  PointCloud cloud;
  const vtkIdType n = grid->GetNumberOfPoints();
  cloud.position.resize(n);
  bool flat = true;
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    cloud.position[i] = Eigen::Vector3d(p[0], p[1], p[2]);
    flat = flat && p[2] == 0.0;
  }
  cloud.dimension = dimension != 0 ? dimension : (flat ? 2 : 3);

  auto scalar_array = [&](const char* name) -> vtkDataArray* {
    vtkDataArray* a = grid->GetPointData()->GetArray(name);
    if (!a) return nullptr;
    if (a->GetNumberOfComponents() != 1 || a->GetNumberOfTuples() != n)
      throw InputError(
          vtu.string(), 0,
          std::string("point data '") + name + "' must have 1 component and one value per point");
    return a;
  };
  if (vtkDataArray* a = scalar_array("material")) {
    cloud.material.resize(n);
    for (vtkIdType i = 0; i < n; ++i) cloud.material[i] = static_cast<int>(a->GetTuple1(i));
  }
  if (vtkDataArray* a = scalar_array("volume")) {
    cloud.volume.resize(n);
    for (vtkIdType i = 0; i < n; ++i) cloud.volume[i] = a->GetTuple1(i);
  }
  if (vtkDataArray* a = scalar_array("mass")) {
    cloud.mass.resize(n);
    for (vtkIdType i = 0; i < n; ++i) cloud.mass[i] = a->GetTuple1(i);
  }
  if (vtkDataArray* a = scalar_array("id")) {
    cloud.id.resize(n);
    for (vtkIdType i = 0; i < n; ++i) cloud.id[i] = static_cast<int>(a->GetTuple1(i));
  }
  if (vtkDataArray* a = grid->GetPointData()->GetArray("velocity");
      a && a->GetNumberOfComponents() == 3 && a->GetNumberOfTuples() == n) {
    cloud.speed.resize(n);
    for (vtkIdType i = 0; i < n; ++i) {
      const double* v = a->GetTuple3(i);
      cloud.speed[i] = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
  }
  if (vtkDataArray* a = liquid ? scalar_array("porosity") : nullptr) {
    cloud.porosity.resize(n);
    for (vtkIdType i = 0; i < n; ++i) cloud.porosity[i] = a->GetTuple1(i);
  }
  return cloud;
}

}  // namespace

PointCloud read_points(const fs::path& vtu, int dimension) {
  return read_cloud(vtu, dimension, false);
}

PointCloud read_liquid_points(const fs::path& vtu, int dimension) {
  PointCloud cloud = read_cloud(vtu, dimension, true);
  // Without volumes the surface would sit half a point spacing too low, a bias as large as
  // the waves of a coarse run; the solver always writes them, so their absence is an error.
  if (cloud.volume.empty() && !cloud.position.empty())
    throw InputError(vtu.string(), 0,
                     "the liquid points have no 'volume' field, which the water surface needs");
  return cloud;
}

double point_spacing(const PointCloud& points, size_t i) {
  if (points.volume.empty() || !(points.volume[i] > 0)) return 0.0;
  double v = points.volume[i];
  // Pore water: the point holds the water of a mixture volume volume / porosity.
  if (!points.porosity.empty() && points.porosity[i] > 0 && points.porosity[i] < 1)
    v /= points.porosity[i];
  return points.dimension == 3 ? std::cbrt(v) : std::sqrt(v);
}

double median_point_spacing(const PointCloud& points) {
  std::vector<double> spacing;
  spacing.reserve(points.volume.size());
  for (size_t i = 0; i < points.volume.size(); ++i)
    if (points.volume[i] > 0) spacing.push_back(point_spacing(points, i));
  if (spacing.empty()) return std::numeric_limits<double>::quiet_NaN();
  // The upper median of an even count: a spacing some point really has.
  auto middle = spacing.begin() + spacing.size() / 2;
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

}  // namespace lituya::post
