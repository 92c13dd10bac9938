# texfilterEmbedSpirv.cmake: texfilter_add_shaders(... EMBED)'s build step, run as
#   cmake -DSPIRV=<module.spv> -DHEADER=<out.h> -DSYMBOL=<name> -DSOURCE=<file name> -P texfilterEmbedSpirv.cmake
# Writes a C++ header that compiles on its own: <cstdint> and `const std::uint32_t SYMBOL[]`, the module's
# words in the host's byte order (SPIR-V files are little-endian words, as every Vulkan host reads them).
# Both compilers' modules go through it, so the header is the same whichever compiled the shader.
foreach(variable SPIRV HEADER SYMBOL SOURCE)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "texfilterEmbedSpirv.cmake: -D${variable}=... missing")
  endif()
endforeach()
file(READ "${SPIRV}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR remainder "${digits} % 8")
if(digits EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "texfilterEmbedSpirv.cmake: ${SPIRV} is not whole 32-bit words (${digits} hex digits)")
endif()
if(NOT hex MATCHES "^03022307")
  message(FATAL_ERROR "texfilterEmbedSpirv.cmake: ${SPIRV} does not start with the SPIR-V magic number")
endif()
# Little-endian bytes b0 b1 b2 b3 -> 0xb3b2b1b0, eight words a line.
set(byte "([0-9a-f][0-9a-f])")
string(REGEX REPLACE "${byte}${byte}${byte}${byte}" "0x\\4\\3\\2\\1," words "${hex}")
set(word "0x[0-9a-f]+,") # CMake's regular expressions have no {8}
string(REGEX REPLACE "(${word}${word}${word}${word}${word}${word}${word}${word})" "\\1\n    " words "${words}")
string(STRIP "${words}" words)
get_filename_component(header_name "${HEADER}" NAME)
file(WRITE "${HEADER}"
     "// ${header_name}: SPIR-V of ${SOURCE}, written by texfilter_add_shaders(... EMBED). Do not edit.\n"
     "#pragma once\n"
     "#include <cstdint>\n"
     "\n"
     "const std::uint32_t ${SYMBOL}[] = {\n"
     "    ${words}\n"
     "};\n")
