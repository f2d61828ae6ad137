# The Adafruit MPU6050 library and its dependency, Adafruit Unified Sensor,
# pinned to a tag's commit like the firmware's other Adafruit libraries
# (src/CMakeLists.txt): FetchContent from GitHub, or offline from local
# copies with
#   -DFETCHCONTENT_SOURCE_DIR_ADAFRUIT_MPU6050=<Adafruit_MPU6050 2.2.8>
#   -DFETCHCONTENT_SOURCE_DIR_ADAFRUIT_UNIFIED_SENSOR=<Adafruit_Sensor 1.1.15>
# (tools/dev passes both when it finds the pinned trees). Neither is a CMake
# project, so only their sources are fetched (SOURCE_SUBDIR that does not
# exist). For an AVR project that already has the target adafruit_busio
# (Adafruit BusIO on Wire and SPI); defines the static libraries
# adafruit_unified_sensor and adafruit_mpu6050, built as they come (-w).
# PlatformIO users get the same versions with
#   lib_deps = adafruit/Adafruit MPU6050@2.2.8, adafruit/Adafruit Unified Sensor@1.1.15
include(FetchContent)
FetchContent_Declare(adafruit_unified_sensor
  GIT_REPOSITORY https://github.com/adafruit/Adafruit_Sensor.git
  GIT_TAG 0a9127a1e886ff1adb4c1b6f5958b24108d55aa6  # 1.1.15
  SOURCE_SUBDIR no-cmake-project)
FetchContent_Declare(adafruit_mpu6050
  GIT_REPOSITORY https://github.com/adafruit/Adafruit_MPU6050.git
  GIT_TAG 049272725553ec135d114b40741211a103af7959  # 2.2.8
  SOURCE_SUBDIR no-cmake-project)
FetchContent_MakeAvailable(adafruit_unified_sensor adafruit_mpu6050)

add_library(adafruit_unified_sensor STATIC ${adafruit_unified_sensor_SOURCE_DIR}/Adafruit_Sensor.cpp)
target_include_directories(adafruit_unified_sensor PUBLIC ${adafruit_unified_sensor_SOURCE_DIR})
target_link_libraries(adafruit_unified_sensor PUBLIC adafruit_busio)
add_library(adafruit_mpu6050 STATIC ${adafruit_mpu6050_SOURCE_DIR}/Adafruit_MPU6050.cpp)
target_include_directories(adafruit_mpu6050 PUBLIC ${adafruit_mpu6050_SOURCE_DIR})
target_link_libraries(adafruit_mpu6050 PUBLIC adafruit_unified_sensor adafruit_busio)
foreach(lib adafruit_unified_sensor adafruit_mpu6050)
  target_compile_options(${lib} PRIVATE -w)
endforeach()
