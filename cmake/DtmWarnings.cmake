# Warning flags for every dtm target; DTM_WERROR turns them into errors (CI).
function(dtm_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        # GCC 12 reports -Wrestrict false positives inside std::string concatenation (GCC bug 105329).
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    # GCC 12 at -O2/-O3 reports a false -Wrestrict inside libstdc++ for `"text" + std::string`
    # (GCC bug 105329); it is not about our code and would fail every -Werror build.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    if(DTM_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()
