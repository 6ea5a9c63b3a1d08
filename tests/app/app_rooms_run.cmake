# One run of the app's room check on the tree at PROJECT_SOURCE_DIR (app_rooms_check.cmake).
cmake_minimum_required(VERSION 3.20)
include(${LAYERS})
fiberbridge_check_app_rooms()
