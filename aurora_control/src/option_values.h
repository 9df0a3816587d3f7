// Command lines whose values may start with '-' (a negative delay or gain,
// which the tools then refuse with their limits): "--kp -1" becomes
// "--kp=-1", and each further number after a multi-value option
// ("--delay 3 -4") its own "--delay=-4" (such an option must compose).
// Otherwise boost reads "-4" as an unknown option.
#pragma once

#include <boost/program_options.hpp>

#include <cctype>
#include <string>
#include <vector>

namespace aurora_control {

inline bool looksNumeric(const std::string& s) {
  const size_t i = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  return i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.');
}

inline std::vector<std::string> joinOptionValues(int argc, char** argv,
                                                 const boost::program_options::options_description& d) {
  std::vector<std::string> out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const boost::program_options::option_description* o =
        a.rfind("--", 0) == 0 && a.find('=') == std::string::npos ? d.find_nothrow(a.substr(2), false) : nullptr;
    // An empty value stays a token of its own (boost refuses "--link="): the tool refuses it by name.
    if (!o || o->semantic()->max_tokens() == 0 || i + 1 >= argc || argv[i + 1][0] == '\0') {
      out.push_back(a);
      continue;
    }
    out.push_back(a + "=" + argv[++i]);
    while (o->semantic()->max_tokens() > 1 && i + 1 < argc && looksNumeric(argv[i + 1])) out.push_back(a + "=" + argv[++i]);
  }
  return out;
}

}  // namespace aurora_control
