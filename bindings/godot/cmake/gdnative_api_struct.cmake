# Writes gdnative_api_struct.gen.h from Godot's gdnative_api.json, as Godot's own generator
# (modules/gdnative/gdnative_builders.py) does, without needing Python:
#   cmake -DAPI_JSON=<gdnative_api.json> -DOUTPUT=<gdnative_api_struct.gen.h> -P gdnative_api_struct.cmake
# Only the typedefs a GDNative library needs: the API type enum and one struct of function pointers
# per API version (core 1.0 with its 1.1, 1.2 successors; each extension and its successors).
# The struct layout must match the engine's exactly: fields in the JSON's order.
cmake_minimum_required(VERSION 3.20)
file(READ "${API_JSON}" api)

# Appends one struct field per function of the JSON array `functions` to `out_var`.
function(append_functions functions out_var)
  set(out "${${out_var}}")
  string(JSON count LENGTH "${functions}")
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON fn GET "${functions}" ${i})
    string(JSON name GET "${fn}" name)
    string(JSON ret GET "${fn}" return_type)
    string(JSON args GET "${fn}" arguments)
    string(JSON nargs LENGTH "${args}")
    set(arglist "")
    if(nargs GREATER 0)
      math(EXPR alast "${nargs} - 1")
      foreach(a RANGE ${alast})
        string(JSON type GET "${args}" ${a} 0)
        string(JSON arg GET "${args}" ${a} 1)
        if(NOT type MATCHES "\\*$")
          string(APPEND type " ")
        endif()
        if(a GREATER 0)
          string(APPEND arglist ", ")
        endif()
        string(APPEND arglist "${type}${arg}")
      endforeach()
    endif()
    if(NOT ret MATCHES "\\*$")
      string(APPEND ret " ")
    endif()
    string(APPEND out "\t${ret}(*${name})(${arglist});\n")
  endforeach()
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

# Appends the structs of `version` (a JSON object with type, version, next, api) and of its
# successors (`next`), newest first; `prefix` names them, `versioned` adds _<major>_<minor>.
function(append_version_structs version prefix versioned out_var)
  set(out "${${out_var}}")
  string(JSON next_type TYPE "${version}" next)
  if(next_type STREQUAL "OBJECT")
    string(JSON next GET "${version}" next)
    append_version_structs("${next}" "${prefix}" TRUE out)
  endif()
  set(name "${prefix}")
  if(versioned)
    string(JSON major GET "${version}" version major)
    string(JSON minor GET "${version}" version minor)
    string(APPEND name "_${major}_${minor}")
  endif()
  string(APPEND out "typedef struct ${name}_api_struct {\n\tunsigned int type;\n"
    "\tgodot_gdnative_api_version version;\n\tconst godot_gdnative_api_struct *next;\n")
  string(JSON functions GET "${version}" api)
  append_functions("${functions}" out)
  string(APPEND out "} ${name}_api_struct;\n\n")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

string(JSON core GET "${api}" core)
string(JSON extensions GET "${api}" extensions)
string(JSON num_extensions LENGTH "${extensions}")
math(EXPR last_extension "${num_extensions} - 1")

string(JSON core_type GET "${core}" type)
set(text "/* THIS FILE IS GENERATED DO NOT EDIT (bindings/godot/cmake/gdnative_api_struct.cmake) */
#ifndef GODOT_GDNATIVE_API_STRUCT_H
#define GODOT_GDNATIVE_API_STRUCT_H

#include <gdnative/gdnative.h>
#include <android/godot_android.h>
#include <arvr/godot_arvr.h>
#include <nativescript/godot_nativescript.h>
#include <net/godot_net.h>
#include <pluginscript/godot_pluginscript.h>
#include <videodecoder/godot_videodecoder.h>

#ifdef __cplusplus
extern \"C\" {
#endif

enum GDNATIVE_API_TYPES {
\tGDNATIVE_${core_type},
")
foreach(i RANGE ${last_extension})
  string(JSON type GET "${extensions}" ${i} type)
  string(APPEND text "\tGDNATIVE_EXT_${type},\n")
endforeach()
string(APPEND text "};\n\n")

foreach(i RANGE ${last_extension})
  string(JSON extension GET "${extensions}" ${i})
  string(JSON name GET "${extension}" name)
  append_version_structs("${extension}" "godot_gdnative_ext_${name}" FALSE text)
endforeach()

# The core 1.0 struct is the one the engine hands over; its successors hang off `next`.
string(JSON core_next_type TYPE "${core}" next)
if(core_next_type STREQUAL "OBJECT")
  string(JSON core_next GET "${core}" next)
  append_version_structs("${core_next}" "godot_gdnative_core" TRUE text)
endif()
string(APPEND text "typedef struct godot_gdnative_core_api_struct {\n\tunsigned int type;\n"
  "\tgodot_gdnative_api_version version;\n\tconst godot_gdnative_api_struct *next;\n"
  "\tunsigned int num_extensions;\n\tconst godot_gdnative_api_struct **extensions;\n")
string(JSON core_functions GET "${core}" api)
append_functions("${core_functions}" text)
string(APPEND text "} godot_gdnative_core_api_struct;

#ifdef __cplusplus
}
#endif

#endif // GODOT_GDNATIVE_API_STRUCT_H
")

# Rewrite only on change, so dependents do not rebuild needlessly.
file(WRITE "${OUTPUT}.tmp" "${text}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
