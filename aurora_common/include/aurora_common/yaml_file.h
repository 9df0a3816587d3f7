// Every YAML file the project reads (vehicle, controller, task, link,
// formation and sweep files) is loaded here: a file that cannot be read or
// parsed, and a mapping that gives a key twice, are refused. YAML says keys
// are unique, yet yaml-cpp keeps the first of a duplicated key and PyYAML
// (roslaunch's rosparam) the last, so the same file flew differently in
// `flight` and in the node; we refuse it instead, naming the key and both
// lines. ROS-free.
#pragma once

#include <sys/stat.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "aurora_common/refusal_text.h"

namespace aurora_common {

namespace yaml_detail {

inline std::string joinKey(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "." + name;
}

inline void refuseDuplicates(const YAML::Node& n, const std::string& where, const std::string& file) {
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) refuseDuplicates(n[i], where + "[" + std::to_string(i) + "]", file);
    return;
  }
  if (!n.IsMap()) return;
  std::map<std::string, int> lines;  // key -> the line (1-based) that first gives it
  for (YAML::const_iterator it = n.begin(); it != n.end(); ++it) {
    const std::string key = it->first.Scalar();
    const int line = it->first.Mark().line + 1;
    const auto seen = lines.emplace(key, line);
    if (!seen.second) {
      throw ConfigError(file + ": '" + joinKey(where, key) + "' is given twice, on lines " +
                        std::to_string(seen.first->second) + " and " + std::to_string(line) +
                        ": give each key once (YAML keys are unique; readers disagree on which one wins)");
    }
    refuseDuplicates(it->second, joinKey(where, key), file);
  }
}

}  // namespace yaml_detail

// The folder of a file's path ("." for a bare name): where the files it
// names by relative paths are looked for first.
inline std::string folderOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

// The root of the YAML file at `path`; `what` names the file's kind in the
// refusal ("link file 'x.yaml' cannot be read: ...").
inline YAML::Node loadYamlFile(const std::string& what, const std::string& path) {
  struct stat st;
  if (path.empty()) throw ConfigError(what + " '' is refused: give the path of a YAML file");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    throw ConfigError(what + " '" + path + "' is a folder: give the path of a YAML file in it");
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ConfigError(what + " '" + path + "' cannot be read (does it exist, and is it a file?)");
  } catch (const YAML::Exception& e) {
    throw ConfigError(what + " '" + path + "' is not valid YAML: " + e.what());
  }
  yaml_detail::refuseDuplicates(root, "", what + " '" + path + "'");
  return root;
}

// The word under `top`.`key` of a YAML root ("" when there is none): what
// chooses a reader or a vehicle (a controller file's controller.name, a
// formation file's formation.shape).
inline std::string yamlWord(const YAML::Node& root, const char* top, const char* key) {
  const YAML::Node word = root.IsMap() && root[top] && root[top].IsMap() ? root[top][key] : YAML::Node();
  return word && word.IsScalar() ? word.as<std::string>() : "";
}

// The same of the YAML file at `path`, before the file is read in full.
inline std::string yamlFileWord(const std::string& what, const std::string& path, const char* top, const char* key) {
  return yamlWord(loadYamlFile(what, path), top, key);
}

}  // namespace aurora_common
