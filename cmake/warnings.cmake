# Compiler warnings for every partimix target; -Werror unless PARTIMIX_WERROR is OFF.
# With PARTIMIX_SANITIZE, targets are built with ASan and UBSan (used by `make test-sanitize`).
function(partimix_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(PARTIMIX_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# GCC 12's flow-based warnings misfire on sanitizer-instrumented code (maybe-uninitialized
# inside std::regex and std::function, mismatched-new-delete on a replaced global operator
# new); the Release build keeps them on.
if(PARTIMIX_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined -Wno-maybe-uninitialized
                      -Wno-mismatched-new-delete)
  add_link_options(-fsanitize=address,undefined)
endif()
