# The harness targets of the fuzz preset (names listed in harnesses.cmake).

# Generated protobuf/gRPC code is protobuf's, not ours: unoptimised and uninstrumented it builds
# in a fifth of the time (the cold fuzz build is what CI waits for).
foreach(proto semnav_proto_common semnav_proto_mapping semnav_proto_planning semnav_proto_relocalization
        semnav_proto_modelproxy semnav_proto_reasoning semnav_grpc_std_clients)
  if(TARGET ${proto})
    target_compile_options(${proto} PRIVATE -O0 -fno-sanitize=all)
  endif()
endforeach()
semnav_library(semnav_fuzz_support SOURCES fuzz_support.cc)
semnav_library(semnav_fuzz_rpc SOURCES rpc_harness.cc DEPS semnav_common gRPC::grpc++ absl::strings)

semnav_fuzzer(world_yaml DEPS semnav_sim_core semnav_fuzz_support)
semnav_fuzzer(service_config DEPS semnav_mapping_server semnav_planning_server semnav_relocalization_server
  semnav_modelproxy_server semnav_reasoning_server semnav_common semnav_fuzz_support)
semnav_fuzzer(stack_config DEPS semnav_launcher_lib semnav_fuzz_support)
semnav_fuzzer(map_store_file DEPS semnav_mapping_core semnav_fuzz_support)
semnav_fuzzer(map_payload DEPS semnav_mapping_core semnav_fuzz_support)
semnav_fuzzer(landmark_map_file DEPS semnav_relocalization_core semnav_fuzz_support)
semnav_fuzzer(octomap_import DEPS semnav_sim_worlds semnav_fuzz_support)
semnav_fuzzer(model_answer DEPS semnav_modelproxy_core semnav_fuzz_support)
semnav_fuzzer(subgoal_json DEPS semnav_reasoning_core semnav_fuzz_support)
semnav_fuzzer(offline_task DEPS semnav_modelproxy_core semnav_fuzz_support)
semnav_fuzzer(rpc_mapping DEPS semnav_mapping_server semnav_fuzz_rpc semnav_fuzz_support)
semnav_fuzzer(rpc_planning DEPS semnav_planning_server semnav_fuzz_rpc)
semnav_fuzzer(rpc_relocalization DEPS semnav_relocalization_server semnav_fuzz_rpc)
semnav_fuzzer(rpc_modelproxy DEPS semnav_modelproxy_server semnav_fuzz_rpc)
semnav_fuzzer(rpc_gateway DEPS semnav_reasoning_server semnav_fuzz_rpc)


# The request sweep against service binaries built here, i.e. with ASan and UBSan
# (ctest asan_request_sweep; docs/dev/fuzzing.md).
add_custom_target(semnav_asan_sweep)
add_dependencies(semnav_asan_sweep semnav-mapping semnav-planning semnav-relocalization semnav-model-proxy
                 semnav-gateway semnav_request_sweep_contract_test)
add_dependencies(semnav_fuzzers semnav_asan_sweep)
