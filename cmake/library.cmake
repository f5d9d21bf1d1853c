# The Rust library built by cargo, as two imported targets (demcontact::demcontact shared,
# demcontact::demcontact_static), and the Fortran module library demcontact::fortran.
# File names come from CMake's platform variables; the libraries a static Rust library needs
# from rustc itself.

find_program(CARGO_EXECUTABLE cargo HINTS "$ENV{HOME}/.cargo/bin" REQUIRED)
get_filename_component(_dc_cargo_bin "${CARGO_EXECUTABLE}" DIRECTORY)
find_program(RUSTC_EXECUTABLE rustc HINTS "${_dc_cargo_bin}" "$ENV{HOME}/.cargo/bin" REQUIRED)
find_package(Threads REQUIRED)
# The C maths library, where the platform has a separate one (not on macOS or Windows).
find_library(DC_LIBM m)
if(NOT DC_LIBM)
  set(DC_LIBM "")
endif()

set(DC_SOVERSION ${PROJECT_VERSION_MAJOR})
set(DC_LIB_DIR "${DEMCONTACT_CARGO_TARGET_DIR}/release")
# What cargo writes: libdemcontact.so / .dylib / demcontact.dll, libdemcontact.a / demcontact.lib.
set(DC_SHARED_NAME "${CMAKE_SHARED_LIBRARY_PREFIX}demcontact${CMAKE_SHARED_LIBRARY_SUFFIX}")
set(DC_STATIC_NAME "${CMAKE_STATIC_LIBRARY_PREFIX}demcontact${CMAKE_STATIC_LIBRARY_SUFFIX}")
set(DC_SHARED "${DC_LIB_DIR}/${DC_SHARED_NAME}")
set(DC_STATIC "${DC_LIB_DIR}/${DC_STATIC_NAME}")
if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  # build.rs gives the shared library the SONAME libdemcontact.so.<major> on Linux; it is
  # installed as libdemcontact.so.<version> with the usual two symlinks.
  set(DC_SONAME "${DC_SHARED_NAME}.${DC_SOVERSION}")
  set(DC_SHARED_REAL "${DC_SHARED_NAME}.${PROJECT_VERSION}")
else()
  set(DC_SONAME "${DC_SHARED_NAME}")
  set(DC_SHARED_REAL "${DC_SHARED_NAME}")
endif()

# Libraries a static Rust library needs on this platform, as rustc reports them for an empty
# staticlib (demcontact links nothing native beyond the standard library).
set(_dc_probe "${CMAKE_BINARY_DIR}/rust_native_libs")
file(MAKE_DIRECTORY "${_dc_probe}")
file(WRITE "${_dc_probe}/empty.rs" "")
execute_process(
  COMMAND "${RUSTC_EXECUTABLE}" --crate-type staticlib --crate-name dc_probe
          --print native-static-libs -o "${_dc_probe}/dc_probe.lib" empty.rs
  WORKING_DIRECTORY "${_dc_probe}" RESULT_VARIABLE _dc_rc OUTPUT_VARIABLE _dc_out ERROR_VARIABLE _dc_out)
if(_dc_rc EQUAL 0 AND _dc_out MATCHES "native-static-libs: ([^\n]*)")
  separate_arguments(DC_STATIC_DEPS NATIVE_COMMAND "${CMAKE_MATCH_1}")
else()
  message(WARNING "demcontact: rustc --print native-static-libs failed; using Threads, ${CMAKE_DL_LIBS} and libm")
  set(DC_STATIC_DEPS Threads::Threads ${CMAKE_DL_LIBS} ${DC_LIBM})
endif()
string(JOIN " " DC_STATIC_DEPS_FLAGS ${DC_STATIC_DEPS})
message(STATUS "demcontact: static library needs ${DC_STATIC_DEPS_FLAGS}")

set(DC_CARGO_ENV "")
if(DEMCONTACT_NATIVE)
  set(DC_CARGO_ENV "${CMAKE_COMMAND}" -E env "RUSTFLAGS=-C target-cpu=native")
endif()
set(DC_SONAME_LINK "")
if(NOT DC_SONAME STREQUAL DC_SHARED_NAME)
  # The loader looks for the SONAME: a symlink next to the library lets build-tree programs run.
  set(DC_SONAME_LINK COMMAND "${CMAKE_COMMAND}" -E create_symlink "${DC_SHARED_NAME}" "${DC_LIB_DIR}/${DC_SONAME}")
endif()

# cargo decides itself what is out of date, so it runs on every build (a no-op when fresh).
add_custom_target(demcontact_cargo ALL
  COMMAND ${DC_CARGO_ENV} "${CARGO_EXECUTABLE}" build --release --lib --bin demcontact --locked -p demcontact
          --manifest-path "${CMAKE_SOURCE_DIR}/Cargo.toml" --target-dir "${DEMCONTACT_CARGO_TARGET_DIR}"
  ${DC_SONAME_LINK}
  BYPRODUCTS "${DC_SHARED}" "${DC_STATIC}"
  WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}"
  USES_TERMINAL
  COMMENT "cargo build --release (demcontact)")

add_library(demcontact_shared SHARED IMPORTED GLOBAL)
set_target_properties(demcontact_shared PROPERTIES
  IMPORTED_LOCATION "${DC_SHARED}"
  IMPORTED_SONAME "${DC_SONAME}"
  INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_SOURCE_DIR}/include")
if(WIN32)
  set_target_properties(demcontact_shared PROPERTIES IMPORTED_IMPLIB "${DC_LIB_DIR}/demcontact.dll.lib")
endif()
add_dependencies(demcontact_shared demcontact_cargo)

add_library(demcontact_static STATIC IMPORTED GLOBAL)
set_target_properties(demcontact_static PROPERTIES
  IMPORTED_LOCATION "${DC_STATIC}"
  INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_SOURCE_DIR}/include"
  INTERFACE_LINK_LIBRARIES "${DC_STATIC_DEPS}")
add_dependencies(demcontact_static demcontact_cargo)

add_library(demcontact::demcontact ALIAS demcontact_shared)
add_library(demcontact::demcontact_static ALIAS demcontact_static)

# ---------------------------------------------------------------- Fortran module (optional)
# `use demcontact`: the generated bind(c) module plus the hand-written one. .mod files are
# compiler-specific, so the .f90 sources are installed too for users of other compilers.
include(CheckLanguage)
check_language(Fortran)
if(CMAKE_Fortran_COMPILER)
  enable_language(Fortran)
  add_library(demcontact_fortran STATIC include/demcontact_c.f90 include/demcontact.f90)
  set_target_properties(demcontact_fortran PROPERTIES
    Fortran_MODULE_DIRECTORY "${CMAKE_BINARY_DIR}/fortran_modules")
  target_include_directories(demcontact_fortran PUBLIC
    "$<BUILD_INTERFACE:${CMAKE_BINARY_DIR}/fortran_modules>")
  add_library(demcontact::fortran ALIAS demcontact_fortran)
else()
  message(STATUS "demcontact: no Fortran compiler: Fortran module and tests skipped")
endif()
