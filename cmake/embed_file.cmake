# Writes a C++ source file that holds the bytes of one file, so the `massprops` tool carries its
# HTML view's assets (page template, script, three.js) without reading anything at run time.
# Script mode: cmake -DINPUT=file -DOUTPUT=file.cc -DSYMBOL=kName -P embed_file.cmake
# The source defines massprops::cli::embedded::SYMBOL (the bytes, followed by a 0 byte) and
# SYMBOL##Size (the number of bytes, without the 0), declared in src/tool/view/view_assets.h.
# INPUT may be empty: the array is then empty (a build without libjs-three).
if(INPUT)
  file(READ "${INPUT}" hex HEX)
  get_filename_component(name "${INPUT}" NAME)
else()
  set(hex "")
  set(name "(nothing)")
endif()
string(LENGTH "${hex}" hex_length)
math(EXPR size "${hex_length} / 2")
# 32 bytes per line, each as 0xNN.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){32})" "\\1\n" bytes "${bytes}")
set(text "// Generated from ${name} by cmake/embed_file.cmake; do not edit.\n")
string(APPEND text "#include \"view_assets.h\"\n\n")
string(APPEND text "namespace massprops::cli::embedded {\n")
string(APPEND text "const unsigned char ${SYMBOL}[] = {\n${bytes}0x00};\n")
string(APPEND text "const std::size_t ${SYMBOL}Size = ${size};\n")
string(APPEND text "}  // namespace massprops::cli::embedded\n")
file(WRITE "${OUTPUT}" "${text}")
