# texfilter_add_shaders(<target> SOURCES <file>... [EMBED] [OUTPUT_DIR <dir>] [TARGET_ENV <env>]
#                       [DEFINES <NAME[=VALUE]>...] [INCLUDE_DIRS <dir>...])
#
# Compiles GLSL that includes texfilter to SPIR-V with glslangValidator, with texfilter's include directory
# on the path, and makes <target> depend on the result.
# - The stage comes from the file name: NAME.STAGE.glsl or NAME.STAGE, STAGE one of vert tesc tese geom
#   frag comp rgen rint rahit rchit rmiss rcall task mesh.
# - Output: OUTPUT_DIR/NAME.STAGE.spv (default OUTPUT_DIR: ${CMAKE_CURRENT_BINARY_DIR}/texfilter_shaders/<target>),
#   listed in <target>'s TEXFILTER_SPIRV property.
# - EMBED: also OUTPUT_DIR/NAME_STAGE.h with `const uint32_t NAME_STAGE[]` (the words of the module), and
#   OUTPUT_DIR on <target>'s private include path, so the program needs no files at run time.
# - TARGET_ENV: glslang's --target-env (default vulkan1.2; ray-tracing stages need vulkan1.2 or newer).
# - Rebuilt when a source, a file it includes (glslang's --depfile) or any texfilter include changes.
include_guard(GLOBAL)

function(texfilter_add_shaders target)
  cmake_parse_arguments(PARSE_ARGV 1 TFS "EMBED" "OUTPUT_DIR;TARGET_ENV" "SOURCES;DEFINES;INCLUDE_DIRS")
  if(TFS_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "texfilter_add_shaders(${target}): unknown arguments ${TFS_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "texfilter_add_shaders(${target}): no such target (create it first)")
  endif()
  if(NOT TFS_SOURCES)
    message(FATAL_ERROR "texfilter_add_shaders(${target}): no SOURCES given")
  endif()
  if(NOT TFS_OUTPUT_DIR)
    set(TFS_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/texfilter_shaders/${target}")
  endif()
  if(NOT TFS_TARGET_ENV)
    set(TFS_TARGET_ENV vulkan1.2)
  endif()

  get_property(include_dir GLOBAL PROPERTY TEXFILTER_INCLUDE_DIR)
  if(TARGET Vulkan::glslangValidator)
    set(glslang "$<TARGET_FILE:Vulkan::glslangValidator>")
  else()
    find_program(TEXFILTER_GLSLANG_EXECUTABLE glslangValidator HINTS ENV VULKAN_SDK PATH_SUFFIXES bin)
    if(NOT TEXFILTER_GLSLANG_EXECUTABLE)
      message(FATAL_ERROR "texfilter_add_shaders: glslangValidator not found (Debian: glslang-tools; or set "
                          "TEXFILTER_GLSLANG_EXECUTABLE)")
    endif()
    set(glslang "${TEXFILTER_GLSLANG_EXECUTABLE}")
  endif()
  file(GLOB texfilter_includes "${include_dir}/texfilter/*.glsl")

  set(flags -V --target-env ${TFS_TARGET_ENV} "-I${include_dir}")
  foreach(dir IN LISTS TFS_INCLUDE_DIRS)
    get_filename_component(dir "${dir}" ABSOLUTE)
    list(APPEND flags "-I${dir}")
  endforeach()
  foreach(define IN LISTS TFS_DEFINES)
    list(APPEND flags "-D${define}")
  endforeach()

  set(outputs)
  set(spirv)
  foreach(source IN LISTS TFS_SOURCES)
    get_filename_component(path "${source}" ABSOLUTE)
    get_filename_component(file "${source}" NAME)
    if(NOT file MATCHES "^(.+)\\.(vert|tesc|tese|geom|frag|comp|rgen|rint|rahit|rchit|rmiss|rcall|task|mesh)(\\.glsl)?$")
      message(FATAL_ERROR "texfilter_add_shaders(${target}): cannot tell the stage of ${source} "
                          "(name it NAME.STAGE.glsl, e.g. sky.frag.glsl)")
    endif()
    set(name "${CMAKE_MATCH_1}")
    set(stage "${CMAKE_MATCH_2}")
    set(module "${TFS_OUTPUT_DIR}/${name}.${stage}.spv")
    # The depfile lists every file the shader includes (the caller's own too), so editing one rebuilds it.
    set(commands COMMAND "${glslang}" ${flags} -S ${stage} --depfile "${module}.d" -o "${module}" "${path}")
    set(produced "${module}")
    if(TFS_EMBED)
      string(MAKE_C_IDENTIFIER "${name}_${stage}" symbol)
      list(APPEND commands COMMAND "${glslang}" ${flags} -S ${stage} --vn ${symbol} -o "${TFS_OUTPUT_DIR}/${symbol}.h"
           "${path}")
      list(APPEND produced "${TFS_OUTPUT_DIR}/${symbol}.h")
    endif()
    add_custom_command(
      OUTPUT ${produced}
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${TFS_OUTPUT_DIR}"
      ${commands}
      DEPENDS "${path}" ${texfilter_includes}
      DEPFILE "${module}.d"
      COMMENT "texfilter: ${file} -> SPIR-V"
      VERBATIM)
    list(APPEND outputs ${produced})
    list(APPEND spirv "${module}")
  endforeach()

  add_custom_target(${target}_texfilter_shaders DEPENDS ${outputs})
  add_dependencies(${target} ${target}_texfilter_shaders)
  if(TFS_EMBED)
    target_include_directories(${target} PRIVATE "${TFS_OUTPUT_DIR}")
  endif()
  set_property(TARGET ${target} APPEND PROPERTY TEXFILTER_SPIRV ${spirv})
endfunction()
