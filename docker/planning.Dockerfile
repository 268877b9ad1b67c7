# semnav-planning: paths, frontiers, exploration goals (port 50052).
# Build from the checkout root (docs/operations.md):
#   docker build -f docker/planning.Dockerfile -t semnav-planning:0.1.0 .
# Debian packages only; the build stage compiles from source, the runtime stage has the runtime
# libraries, the binary, `semnav` (for `semnav probe`, the health check) and its default config.
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
RUN cmake --preset release -DSEMNAV_SERVICES="planning" -DSEMNAV_SHARED_DATA_DIR=/usr/local/share/semnav \
 && cmake --build --preset release --target semnav-planning semnav

FROM debian:bookworm
RUN apt-get update \
 && apt-get install -y --no-install-recommends \
      libabsl20220623 libgrpc++1.51 libgrpc29 libprotobuf32 libyaml-cpp0.7 \
 && rm -rf /var/lib/apt/lists/* \
 && useradd --system --uid 10001 --user-group --home-dir /var/lib/semnav --create-home \
      --shell /usr/sbin/nologin semnav
COPY --from=build /src/build/release/bin/semnav-planning /src/build/release/bin/semnav /usr/local/bin/
COPY deploy/k8s/config/planning.yaml /etc/semnav/planning.yaml
USER semnav
WORKDIR /var/lib/semnav
EXPOSE 50052
HEALTHCHECK --interval=10s --timeout=5s --start-period=20s --retries=3 \
  CMD ["semnav", "probe", "--addr", "127.0.0.1:50052", "--service", "semnav.planning.v1.PlanningService"]
ENTRYPOINT ["semnav-planning"]
CMD ["--config", "/etc/semnav/planning.yaml"]
