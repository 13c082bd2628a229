# Project-wide compile settings, applied per target with snow_set_options().
# Determinism (docs/design.md "Determinism"): never -ffast-math; -ffp-contract=off so no FMA fusion
# changes results between scalar/SIMD or Debug/Release builds.
# GCC: -fno-tree-loop-distribute-patterns, so a vectorised loop that also copies
# an array (integrate keeps each flake's path start) stays one loop; GCC would
# split the copy out into memmove calls, a second pass over the block (a sixth
# of the 1M-flake tick; docs/performance.md).
function(snow_set_options target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Werror
        -ffp-contract=off -fno-trapping-math
        $<$<CXX_COMPILER_ID:GNU>:-fno-tree-loop-distribute-patterns>)
    if(SNOW_NATIVE)
        target_compile_options(${target} PRIVATE -march=native)
    endif()
    if(SNOW_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                 -fno-sanitize-recover=all)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
    if(SNOW_FUZZ) # coverage for libFuzzer; fuzz/ links the fuzzer's main
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link
            -fsanitize-coverage-ignorelist=${PROJECT_SOURCE_DIR}/fuzz/coverage_ignore.txt)
    endif()
endfunction()

# The default allocator (ecs/host_memory.cpp) calls the sized aligned
# ::operator delete, which Clang 14 declares only under -fsized-deallocation
# (GCC: on from C++14). A usage requirement: PUBLIC, and exported with the
# installed target, evaluated for the consumer's compiler.
function(snow_require_sized_deallocation target)
    target_compile_options(${target} PUBLIC
        $<$<COMPILE_LANG_AND_ID:CXX,Clang,AppleClang>:-fsized-deallocation>)
endfunction()

# Generates ${out} (a .cpp) defining snow::${symbol}() returning ${input}'s bytes.
function(snow_embed_file input out symbol)
    add_custom_command(OUTPUT ${out}
        COMMAND ${CMAKE_COMMAND} -DINPUT=${input} -DOUTPUT=${out} -DSYMBOL=${symbol}
                -P ${PROJECT_SOURCE_DIR}/cmake/EmbedFile.cmake
        DEPENDS ${input} ${PROJECT_SOURCE_DIR}/cmake/EmbedFile.cmake
        COMMENT "Embedding ${input}")
endfunction()
