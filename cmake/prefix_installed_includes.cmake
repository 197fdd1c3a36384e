# SPDX-License-Identifier: Apache-2.0
# Run by `cmake --install` after the headers are copied (CMakeLists.txt, "The library"): each
# installed header's includes of hmcr's layers, "LAYER/name.h", become "hmcr/LAYER/name.h", the
# prefix under which an outside project includes them. HMCR_LAYERS names the layers.
set(root "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/include/hmcr")
string(REPLACE ";" "|" layers "${HMCR_LAYERS}")
file(GLOB_RECURSE headers "${root}/*.h")
foreach(header ${headers})
  file(READ "${header}" text)
  string(REGEX REPLACE "#include \"(${layers})/" "#include \"hmcr/\\1/" prefixed "${text}")
  if(NOT prefixed STREQUAL text)
    file(WRITE "${header}" "${prefixed}")
  endif()
endforeach()
