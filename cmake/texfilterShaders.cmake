# texfilter_add_shaders(<target> SOURCES <file>... [EMBED] [OUTPUT_DIR <dir>] [TARGET_ENV <env>]
#                       [COMPILER glslangValidator|glslc] [OPTIMIZE <condition>] [DEBUG_INFO <condition>]
#                       [OPTIONS <flag>...] [DEFINES <NAME[=VALUE]>...] [INCLUDE_DIRS <dir>...])
#
# Compiles GLSL that includes texfilter to SPIR-V, with texfilter's include directory on the path, and makes
# <target> depend on the result. Call it as often as you like on one target (each call is its own custom
# target, <target>_texfilter_shaders, then _2, _3 ...).
# - The stage comes from the file name: NAME.STAGE.glsl or NAME.STAGE, STAGE one of vert tesc tese geom
#   frag comp rgen rint rahit rchit rmiss rcall task mesh.
# - COMPILER: glslangValidator or glslc (default: the cache variable TEXFILTER_SHADER_COMPILER, itself
#   glslangValidator by default). Found as Vulkan::glslangValidator / Vulkan::glslc where FindVulkan made
#   them, else on PATH or $VULKAN_SDK/bin (TEXFILTER_GLSLANG_EXECUTABLE / TEXFILTER_GLSLC_EXECUTABLE).
# - OPTIMIZE, DEBUG_INFO: a boolean, or a generator expression that gives one, so each configuration of a
#   multi-config generator can differ (e.g. OPTIMIZE $<NOT:$<CONFIG:Debug>> DEBUG_INFO $<CONFIG:Debug>).
#   Default: neither. OPTIMIZE is glslc's -O (performance) or glslangValidator's -Os (its only optimiser;
#   it needs a glslang built with SPIRV-Tools, as Debian's is). DEBUG_INFO is -g with either (OpSource,
#   OpLine, OpName).
# - OPTIONS: more flags, passed to the compiler as written; generator expressions allowed, one flag each
#   (OPTIONS $<$<CONFIG:Debug>:-gVS> "$<$<CONFIG:Release>:-Werror>"). The two compilers' flags differ.
# - Output: OUTPUT_DIR/NAME.STAGE.spv (default OUTPUT_DIR: ${CMAKE_CURRENT_BINARY_DIR}/texfilter_shaders/<target>;
#   with a multi-config generator OUTPUT_DIR/<CONFIG>/...), listed in <target>'s TEXFILTER_SPIRV property.
#   Sources of one call that share NAME.STAGE (a/blur.comp.glsl, b/blur.comp.glsl) keep their folder,
#   relative to the calling CMakeLists.txt's (outside it: "h" and 8 hex digits of the folder's path):
#   OUTPUT_DIR/a/blur.comp.spv. Two calls that would write one file are an error.
# - EMBED: also OUTPUT_DIR/NAME_STAGE.h with `const std::uint32_t NAME_STAGE[]` (the words of the module;
#   it includes <cstdint> and compiles on its own), and OUTPUT_DIR on <target>'s private include path, so the
#   program needs no files at run time. Kept folders go into both: "a/blur_comp.h" declares a_blur_comp.
# - TARGET_ENV: the compiler's --target-env (default vulkan1.2; ray-tracing stages need vulkan1.2 or newer).
#   Compute quads (TF_COMPUTE_QUADS, GL_KHR_shader_subgroup_quad) need SPIR-V 1.3: vulkan1.1 or newer.
# - DEFINES: -D for each; INCLUDE_DIRS: -I for each (relative to the calling CMakeLists.txt's folder).
# - Rebuilt when a source, a file it includes (the compiler's depfile) or any texfilter include changes.
include_guard(GLOBAL)

set(TEXFILTER_SHADER_COMPILER glslangValidator CACHE STRING
    "GLSL compiler texfilter_add_shaders uses unless a call names one (COMPILER): glslangValidator or glslc")
set_property(CACHE TEXFILTER_SHADER_COMPILER PROPERTY STRINGS glslangValidator glslc)
# The header writer runs as a script at build time; functions run in their caller's scope, so its path
# travels as a global property.
set_property(GLOBAL PROPERTY TEXFILTER_EMBED_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/texfilterEmbedSpirv.cmake")

# The command line (in <out>) of compiler <name>: Vulkan's imported target, else a program found once.
function(_texfilter_shader_compiler name out)
  if(name STREQUAL "glslangValidator")
    set(imported Vulkan::glslangValidator)
    set(cache TEXFILTER_GLSLANG_EXECUTABLE)
    set(package glslang-tools)
  elseif(name STREQUAL "glslc")
    set(imported Vulkan::glslc)
    set(cache TEXFILTER_GLSLC_EXECUTABLE)
    set(package glslc)
  else()
    message(FATAL_ERROR "texfilter_add_shaders: COMPILER (or TEXFILTER_SHADER_COMPILER) is '${name}'; "
                        "it must be glslangValidator or glslc")
  endif()
  if(TARGET ${imported})
    set(${out} "$<TARGET_FILE:${imported}>" PARENT_SCOPE)
    return()
  endif()
  find_program(${cache} ${name} HINTS ENV VULKAN_SDK PATH_SUFFIXES bin)
  if(NOT ${cache})
    message(FATAL_ERROR "texfilter_add_shaders: ${name} not found (Debian: ${package}; or set ${cache})")
  endif()
  set(${out} "${${cache}}" PARENT_SCOPE)
endfunction()

# Appends <flag> to list <out> when <condition> holds: at once for a plain boolean, as a generator
# expression when the condition is one (evaluated per configuration).
function(_texfilter_flag_if condition flag out)
  if(condition MATCHES "\\$<")
    list(APPEND ${out} "$<$<BOOL:${condition}>:${flag}>")
  elseif(condition)
    list(APPEND ${out} "${flag}")
  endif()
  set(${out} "${${out}}" PARENT_SCOPE)
endfunction()

function(texfilter_add_shaders target)
  cmake_parse_arguments(PARSE_ARGV 1 TFS "EMBED" "OUTPUT_DIR;TARGET_ENV;COMPILER;OPTIMIZE;DEBUG_INFO"
                        "SOURCES;DEFINES;INCLUDE_DIRS;OPTIONS")
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
  get_filename_component(TFS_OUTPUT_DIR "${TFS_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  if(NOT TFS_TARGET_ENV)
    set(TFS_TARGET_ENV vulkan1.2)
  endif()
  if(NOT TFS_COMPILER)
    set(TFS_COMPILER "${TEXFILTER_SHADER_COMPILER}")
  endif()
  _texfilter_shader_compiler("${TFS_COMPILER}" compiler)
  # Each configuration of a multi-config generator gets its own modules (its flags may differ).
  get_property(multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
  set(out_dir "${TFS_OUTPUT_DIR}")
  if(multi_config)
    string(APPEND out_dir "/$<CONFIG>")
  endif()

  get_property(include_dir GLOBAL PROPERTY TEXFILTER_INCLUDE_DIR)
  get_property(embed_script GLOBAL PROPERTY TEXFILTER_EMBED_SCRIPT)
  file(GLOB_RECURSE texfilter_includes "${include_dir}/texfilter/*.glsl")

  # Flags both compilers share, spelled for the one chosen.
  set(flags)
  if(TFS_COMPILER STREQUAL "glslc")
    list(APPEND flags "--target-env=${TFS_TARGET_ENV}" -I "${include_dir}")
    set(optimize_flag -O)
  else()
    list(APPEND flags -V --target-env ${TFS_TARGET_ENV} "-I${include_dir}")
    set(optimize_flag -Os)
  endif()
  foreach(dir IN LISTS TFS_INCLUDE_DIRS)
    get_filename_component(dir "${dir}" ABSOLUTE)
    list(APPEND flags "-I${dir}")
  endforeach()
  foreach(define IN LISTS TFS_DEFINES)
    list(APPEND flags "-D${define}")
  endforeach()
  _texfilter_flag_if("${TFS_OPTIMIZE}" ${optimize_flag} flags)
  _texfilter_flag_if("${TFS_DEBUG_INFO}" -g flags)
  list(APPEND flags ${TFS_OPTIONS})

  # NAME.STAGE of every source; sources that share one keep their folder.
  set(paths)
  set(keys)
  foreach(source IN LISTS TFS_SOURCES)
    get_filename_component(path "${source}" ABSOLUTE)
    get_filename_component(file "${source}" NAME)
    if(NOT file MATCHES "^(.+)\\.(vert|tesc|tese|geom|frag|comp|rgen|rint|rahit|rchit|rmiss|rcall|task|mesh)(\\.glsl)?$")
      message(FATAL_ERROR "texfilter_add_shaders(${target}): cannot tell the stage of ${source} "
                          "(name it NAME.STAGE.glsl, e.g. sky.frag.glsl)")
    endif()
    if(path IN_LIST paths)
      message(FATAL_ERROR "texfilter_add_shaders(${target}): ${source} is listed twice")
    endif()
    list(APPEND paths "${path}")
    list(APPEND keys "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")
  endforeach()

  set(outputs)
  set(spirv)
  set(symbols)
  foreach(path key IN ZIP_LISTS paths keys)
    get_filename_component(file "${path}" NAME)
    string(REGEX MATCH "^(.+)\\.([a-z]+)$" unused "${key}")
    set(name "${CMAKE_MATCH_1}")
    set(stage "${CMAKE_MATCH_2}")
    set(sharing 0)
    foreach(other IN LISTS keys)
      if(other STREQUAL key)
        math(EXPR sharing "${sharing} + 1")
      endif()
    endforeach()
    set(folder "")
    if(sharing GREATER 1)
      get_filename_component(dir "${path}" DIRECTORY)
      file(RELATIVE_PATH folder "${CMAKE_CURRENT_SOURCE_DIR}" "${dir}")
      if(folder MATCHES "^\\.\\.(/|$)" OR IS_ABSOLUTE "${folder}")
        string(SHA1 hash "${dir}")
        string(SUBSTRING "${hash}" 0 8 hash)
        set(folder "h${hash}")
      endif()
      if(folder)
        string(APPEND folder "/")
      endif()
    endif()
    set(module "${out_dir}/${folder}${name}.${stage}.spv")

    # One file, one call: a second call writing the same module would race the first.
    get_property(owner GLOBAL PROPERTY "TEXFILTER_SHADER_OUTPUT:${module}")
    if(owner)
      message(FATAL_ERROR "texfilter_add_shaders(${target}): ${module} is already written for ${owner}; give "
                          "this call its own OUTPUT_DIR, or list both sources in one call (they then keep their folders)")
    endif()
    set_property(GLOBAL PROPERTY "TEXFILTER_SHADER_OUTPUT:${module}" "${path}")

    get_filename_component(module_dir "${module}" DIRECTORY)
    set(commands COMMAND "${CMAKE_COMMAND}" -E make_directory "${module_dir}")
    # The depfile lists every file the shader includes (the caller's own too), so editing one rebuilds it.
    if(TFS_COMPILER STREQUAL "glslc")
      list(APPEND commands COMMAND "${compiler}" ${flags} -fshader-stage=${stage} -MD -MF "${module}.d"
           -o "${module}" "${path}")
    else()
      list(APPEND commands COMMAND "${compiler}" ${flags} -S ${stage} --depfile "${module}.d" -o "${module}"
           "${path}")
    endif()
    set(produced "${module}")
    if(TFS_EMBED)
      string(MAKE_C_IDENTIFIER "${name}_${stage}" leaf)
      string(MAKE_C_IDENTIFIER "${folder}${name}_${stage}" symbol)
      if(symbol IN_LIST symbols)
        message(FATAL_ERROR "texfilter_add_shaders(${target}): two sources would embed as ${symbol}; rename one")
      endif()
      list(APPEND symbols "${symbol}")
      set(header "${out_dir}/${folder}${leaf}.h")
      list(APPEND commands COMMAND "${CMAKE_COMMAND}" "-DSPIRV=${module}" "-DHEADER=${header}" "-DSYMBOL=${symbol}"
           "-DSOURCE=${file}" -P "${embed_script}")
      list(APPEND produced "${header}")
    endif()
    add_custom_command(
      OUTPUT ${produced}
      ${commands}
      DEPENDS "${path}" ${texfilter_includes} ${embed_script}
      DEPFILE "${module}.d"
      COMMENT "texfilter: ${file} -> SPIR-V (${TFS_COMPILER})"
      COMMAND_EXPAND_LISTS
      VERBATIM)
    list(APPEND outputs ${produced})
    list(APPEND spirv "${module}")
  endforeach()

  # One custom target a call: <target>_texfilter_shaders, then _2, _3 ...
  get_property(calls TARGET ${target} PROPERTY TEXFILTER_SHADER_CALLS)
  if(NOT calls)
    set(calls 0)
  endif()
  math(EXPR calls "${calls} + 1")
  set(custom ${target}_texfilter_shaders)
  if(calls GREATER 1)
    set(custom ${target}_texfilter_shaders_${calls})
  endif()
  while(TARGET ${custom})
    math(EXPR calls "${calls} + 1")
    set(custom ${target}_texfilter_shaders_${calls})
  endwhile()
  set_property(TARGET ${target} PROPERTY TEXFILTER_SHADER_CALLS ${calls})
  add_custom_target(${custom} DEPENDS ${outputs})
  add_dependencies(${target} ${custom})
  if(TFS_EMBED)
    target_include_directories(${target} PRIVATE "${out_dir}")
  endif()
  set_property(TARGET ${target} APPEND PROPERTY TEXFILTER_SPIRV ${spirv})
endfunction()
