# Warning flags for every dtm target; DTM_WERROR turns them into errors (CI).
function(dtm_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion)
    if(DTM_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()
