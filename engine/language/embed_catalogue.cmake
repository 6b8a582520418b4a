# cmake -DIN=<file.mo> -DOUT=<file.cpp> -DNAME=<symbol> -P embed_catalogue.cmake
# Writes the compiled catalogue's bytes as a C++ array, so that the programs carry their
# translations and find no file at run time.
file(READ "${IN}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR size "${digits} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x..,){16})" "\\1\n    " bytes "${bytes}")
file(WRITE "${OUT}.tmp"
     "// Written by engine/language/embed_catalogue.cmake from ${IN}: do not edit.\n"
     "#include <cstddef>\n\nnamespace lamina {\n\n"
     "extern const unsigned char ${NAME}[] = {\n    ${bytes}\n};\n"
     "extern const std::size_t ${NAME}_size = ${size};\n\n}  // namespace lamina\n")
file(RENAME "${OUT}.tmp" "${OUT}")
