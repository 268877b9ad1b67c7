# Every harness: fuzz_<name> is built from <name>_fuzzer.cc (fuzzers.cmake), seeded from
# corpus/<name>/ and replays regressions/<name>/.
set(SEMNAV_FUZZ_HARNESSES
  world_yaml          # clients/sim world files (read through ConfigReader)
  service_config      # each service's config file: log_level, server, and its own section
  stack_config        # the launcher's stack YAML
  map_store_file      # mapping's .snmap file (header, size, CRC-32) and the payload inside
  map_payload         # mapping's saved-map payload: OcTree, scene-graph JSON, labelled points, grid
  landmark_map_file   # relocalization's landmark map file
  octomap_import      # the simulator's OctoMap (.bt) world import
  model_answer        # OpenAI, Anthropic, DashScope answer and error bodies, embeddings, JSON answers
  subgoal_json        # the gateway's model answers: subgoal lists and match_target answers
  offline_task        # the model proxy's offline task objects (candidates from the scene graph)
  rpc_mapping         # every request of each service, parsed and served in process
  rpc_planning
  rpc_relocalization
  rpc_modelproxy
  rpc_gateway)
