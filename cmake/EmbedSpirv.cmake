# twinray_embed_spirv(HEADER SOURCE NAME TARGET_ENV [DEFINES...]): compiles the GLSL shader
# SOURCE with glslangValidator at build time (a compile error fails the build) into HEADER, a C
# header holding the SPIR-V words as the array spirv_<NAME>; each DEFINE is passed as -D. Core headers resolve as "core/x.h" from
# the repository root; edits to any included file trigger a rebuild (depfile).
function(twinray_embed_spirv header source name target_env)
  set(defines)
  foreach(d ${ARGN})
    list(APPEND defines -D${d})
  endforeach()
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${GLSLANG_VALIDATOR} -V --target-env ${target_env} -I${CMAKE_SOURCE_DIR} ${defines}
            --vn spirv_${name} --depfile ${header}.d -o ${header} ${source}
    DEPENDS ${source}
    DEPFILE ${header}.d
    COMMENT "glslangValidator ${source}"
    VERBATIM)
endfunction()
