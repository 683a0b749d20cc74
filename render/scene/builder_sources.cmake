# The scene builder's sources (owned by the runtime engineer), added to rts_render.
target_sources(rts_render PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/params.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_builder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_dump.cpp
  ${CMAKE_CURRENT_LIST_DIR}/obj_loader.cpp)
