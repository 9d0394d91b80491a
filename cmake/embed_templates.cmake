# Writes OUT, a C++ file holding the text of each file in FILES (a ;-separated list) in a map
# keyed by file name: the engine templates of dem-scripts/ travel inside the iwb binary.
file(WRITE ${OUT} "// Generated from dem-scripts/ by cmake/embed_templates.cmake; do not edit.\n"
                  "#include <map>\n#include <string>\nnamespace iwb::dem {\n"
                  "const std::map<std::string, std::string>& ${FUNCTION}() {\n"
                  "  static const std::map<std::string, std::string> t{\n")
foreach(f ${FILES})
  get_filename_component(name ${f} NAME)
  file(READ ${f} content)
  file(APPEND ${OUT} "    {\"${name}\", R\"IWBTEMPLATE(${content})IWBTEMPLATE\"},\n")
endforeach()
file(APPEND ${OUT} "  };\n  return t;\n}\n}  // namespace iwb::dem\n")
