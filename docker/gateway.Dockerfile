# semnav-gateway: instructions -> subgoals -> goals -> robot commands; operator API (port 50050).
# Build from the checkout root (docs/operations.md):
#   docker build -f docker/gateway.Dockerfile --build-context shared-data=../shared/data -t semnav-gateway:0.1.0 .
# Debian packages only; the build stage compiles from source, the runtime stage has the runtime
# libraries, the binary, `semnav` (for `semnav probe`, the health check), its default config and data.
FROM debian:bookworm AS build
RUN apt-get update \
 && apt-get install -y --no-install-recommends \
      g++ cmake ninja-build pkg-config \
      libgrpc++-dev protobuf-compiler-grpc libprotobuf-dev protobuf-compiler grpc-proto libabsl-dev \
      libeigen3-dev liboctomap-dev \
      libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-dnn-dev \
      libyaml-cpp-dev nlohmann-json3-dev libicu-dev libcurl4-openssl-dev libcpp-httplib-dev \
      libgtest-dev libgmock-dev libbenchmark-dev \
 && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY CMakeLists.txt CMakePresets.json ./
COPY cmake cmake
COPY protos protos
COPY services services
COPY clients clients
COPY tests tests
COPY deploy/local.yaml deploy/local.yaml
RUN cmake --preset release -DSEMNAV_SERVICES="mapping;planning;reasoning" -DSEMNAV_SHARED_DATA_DIR=/usr/local/share/semnav \
 && cmake --build --preset release --target semnav-gateway semnav

FROM debian:bookworm
RUN apt-get update \
 && apt-get install -y --no-install-recommends \
      libabsl20220623 libgrpc++1.51 libgrpc29 libprotobuf32 libyaml-cpp0.7 libicu72 \
      libopencv-core406 libopencv-imgproc406 libopencv-imgcodecs406 \
 && rm -rf /var/lib/apt/lists/* \
 && useradd --system --uid 10001 --user-group --home-dir /var/lib/semnav --create-home \
      --shell /usr/sbin/nologin semnav
COPY --from=build /src/build/release/bin/semnav-gateway /src/build/release/bin/semnav /usr/local/bin/
COPY deploy/k8s/config/gateway.yaml /etc/semnav/gateway.yaml
COPY services/common/lexicon/lexicon.tsv /usr/local/share/semnav/lexicon.tsv
# The commonsense prior of SEMANTIC_FRONTIER exploration (ConceptNet /r/AtLocation, CC BY-SA 4.0),
# the same folder as in the model-proxy image; gateway.prior_path points into it.
COPY --from=shared-data object-priors/conceptnet_atlocation_coco80 /usr/local/share/semnav/object-priors/conceptnet_atlocation_coco80
USER semnav
WORKDIR /var/lib/semnav
EXPOSE 50050
HEALTHCHECK --interval=10s --timeout=5s --start-period=20s --retries=3 \
  CMD ["semnav", "probe", "--addr", "127.0.0.1:50050", "--service", "semnav.reasoning.v1.OperatorService"]
ENTRYPOINT ["semnav-gateway"]
CMD ["--config", "/etc/semnav/gateway.yaml"]
