// motostab._core.Scenario: a scenario source (the file read once, or a tree from a Python dict) with
// typed parameter changes, loaded and validated by the same strict reader as the command line.
#include <dlfcn.h>
#include <yaml-cpp/yaml.h>

#include <iostream>
#include <mutex>

#include "io/number.h"
#include "plugins/builtin.h"
#include "python/bind_scenario.h"
#include "scenario/parameter_paths.h"

namespace motostab::python {

using io::InputError;
using scenario::ParameterOverrides;
using scenario::ScenarioSource;

namespace {

// A NumPy array (or the like) of one or more dimensions: a list, not a number.
bool isArray(const py::handle& v) { return py::hasattr(v, "ndim") && py::hasattr(v, "tolist") && v.attr("ndim").cast<int>() > 0; }

// A Python value as a YAML node: numbers in the shortest text that reads back to the same double,
// mappings with string keys, sequences; anything else is an InputError naming `path`.
YAML::Node toYaml(const py::handle& v, const std::string& path) {
  if (v.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(v)) return YAML::Node(v.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::str>(v)) return YAML::Node(v.cast<std::string>());
  if (py::isinstance<py::dict>(v)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [key, value] : v.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw InputError({"", 0, 0, path}, "a mapping key must be a string");
      const std::string k = key.cast<std::string>();
      map[k] = toYaml(value, path.empty() ? k : path + "." + k);
    }
    return map;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    YAML::Node seq(YAML::NodeType::Sequence);
    size_t i = 0;
    for (const auto& item : v) seq.push_back(toYaml(item, path + "[" + std::to_string(i++) + "]"));
    return seq;
  }
  const auto object = py::reinterpret_borrow<py::object>(v);
  if (isArray(v)) return toYaml(object.attr("tolist")(), path);
  if (PyIndex_Check(v.ptr())) return YAML::Node(py::str(py::int_(object)).cast<std::string>());
  if (PyFloat_Check(v.ptr()) || py::hasattr(v, "__float__"))
    return YAML::Node(io::formatShortest(py::float_(object).cast<double>()));
  throw InputError({"", 0, 0, path}, "a " + py::str(v.get_type().attr("__name__")).cast<std::string>() +
                                         " cannot be a scenario value (numbers, strings, booleans, None, dicts and lists can)");
}

// A YAML node as Python values: integers and other finite numbers as int and float, true/false as
// bool, null as None, other scalars as str.
py::object yamlToPython(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict out;
      for (const auto& kv : node) out[py::str(kv.first.Scalar())] = yamlToPython(kv.second);
      return std::move(out);
    }
    case YAML::NodeType::Sequence: {
      py::list out;
      for (const auto& item : node) out.append(yamlToPython(item));
      return std::move(out);
    }
    case YAML::NodeType::Scalar: {
      const std::string& text = node.Scalar();
      if (node.Tag() != "!") {  // an unquoted scalar may be a number or a boolean
        if (text == "true") return py::bool_(true);
        if (text == "false") return py::bool_(false);
        const auto number = io::parseFiniteNumber(text);
        if (number) {
          const bool integral = !text.empty() && text.find_first_not_of("+-0123456789") == std::string::npos;
          if (integral) return py::int_(py::str(text));
          return py::float_(*number);
        }
      }
      return py::str(text);
    }
    default:
      return py::none();
  }
}

// Plugin libraries (docs/plugins.md) resolve motostab's symbols from the program that loads them; here
// that is this extension, which Python opens with RTLD_LOCAL. Before the first scenario that names
// plugins, the extension is opened again with RTLD_GLOBAL (RTLD_NOLOAD: the loaded copy), so that its
// symbols resolve the plugins' and nothing changes for Python sessions without plugins.
void exportSymbolsForPlugins() {
  static std::once_flag once;
  std::call_once(once, [] {
    Dl_info info;
    if (dladdr(reinterpret_cast<void*>(&exportSymbolsForPlugins), &info) && info.dli_fname)
      dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL);
  });
}

}  // namespace

ScenarioHandle::ScenarioHandle(std::shared_ptr<const ScenarioSource> src, ParameterOverrides ch)
    : source(std::move(src)), changes(std::move(ch)) {
  if (makeTree()["plugins"]) exportSymbolsForPlugins();
  // The plugin sections are read once here (their files kept, their warnings logged, not printed).
  scenario = std::make_shared<const scenario::Scenario>(callQuietly([&] {
    scenario::Scenario s = source->load(changes);
    plugins::makeBuiltinRegistry().readScenarioSections(s);
    for (const scenario::ScenarioWarning& w : s.warnings)
      if (w.check == scenario::ScenarioWarning::Check::PluginInput)
        std::cerr << "warning: " << w.where.describe() << ": " << w.message << "\n";
    return s;
  }));
}

ScenarioHandle ScenarioHandle::withChanges(const py::dict& values) const {
  ParameterOverrides next = changes;
  ParameterOverrides added;
  for (const auto& [key, value] : values) {
    const std::string path = py::str(key);
    const bool number = !py::isinstance<py::bool_>(value) && !isArray(value) &&
                        (PyIndex_Check(value.ptr()) || PyFloat_Check(value.ptr()) || py::hasattr(value, "__float__"));
    if (number) added.set(path, py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());  // full precision
    else if (py::isinstance<py::str>(value)) added.set(path, value.cast<std::string>());            // a switch
    else added.setNode(path, toYaml(value, path));                                                   // a section
  }
  next.append(added);
  return ScenarioHandle(source, next);
}

YAML::Node ScenarioHandle::makeTree() const { return source->makeTree(changes); }

void bindScenario(py::module_& m) {
  py::class_<ScenarioHandle>(m, "Scenario", "A loaded, validated scenario (see motostab.Scenario)")
      .def_static(
          "load", [](const std::string& path) { return ScenarioHandle(std::make_shared<const ScenarioSource>(path), {}); },
          py::arg("path"))
      .def_static(
          "from_tree",
          [](const py::dict& tree, const std::string& name) {
            return ScenarioHandle(std::make_shared<const ScenarioSource>(toYaml(tree, ""), name), {});
          },
          py::arg("tree"), py::arg("name"))
      .def("with_changes", &ScenarioHandle::withChanges, py::arg("changes"))
      .def(
          "with_assignments",  // the source with exactly these --set assignments (replacing the changes)
          [](const ScenarioHandle& h, const std::vector<std::string>& assignments) {
            return ScenarioHandle(h.source, ParameterOverrides(assignments));
          },
          py::arg("assignments"))
      .def_property_readonly("name", [](const ScenarioHandle& h) { return h.scenario->name; })
      .def_property_readonly("description", [](const ScenarioHandle& h) { return h.scenario->description; })
      .def_property_readonly("file", [](const ScenarioHandle& h) { return h.source->getFile(); })
      .def_property_readonly("overrides", [](const ScenarioHandle& h) { return h.changes.format(); })
      .def_property_readonly("speeds",
                             [](const ScenarioHandle& h) {
                               const auto& s = h.scenario->speeds;
                               return py::make_tuple(s.start, s.stop, s.step);
                             })
      .def_property_readonly("wheelbase_m", [](const ScenarioHandle& h) { return h.scenario->geometry.wheelbase; })
      .def("to_dict", [](const ScenarioHandle& h) { return yamlToPython(h.makeTree()); })
      .def("to_yaml",
           [](const ScenarioHandle& h) {
             YAML::Emitter out;
             out << h.makeTree();
             return std::string(out.c_str()) + "\n";
           })
      .def("get", [](const ScenarioHandle& h, const std::string& path) { return scenario::getScalarParameter(h.makeTree(), path); },
           py::arg("path"))
      .def("parameters", [](const ScenarioHandle& h) {
        py::dict out;
        const YAML::Node tree = h.makeTree();
        const auto sections = plugins::listSectionFields(plugins::makeScenarioRegistry(*h.scenario));
        for (const auto& p : scenario::listScalarParameters(tree, sections))
          out[py::str(p.path)] = p.value;
        return out;
      });
}

}  // namespace motostab::python
