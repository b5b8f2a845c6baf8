# penumbra_set_warnings(target): the project's warning level, errors in CI.
function(penumbra_set_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive-)
    if(PENUMBRA_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE /WX)
    endif()
    return()
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference
    # `VkFooInfo info{VK_STRUCTURE_TYPE_FOO}` zero-initialises the rest on purpose.
    -Wno-missing-field-initializers)
  if(PENUMBRA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
