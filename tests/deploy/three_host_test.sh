#!/usr/bin/env bash
# Three hosts in Linux network namespaces joined by veth pairs, each running the shipped configs
# of deploy/systemd/etc/semnav with mTLS and bearer tokens:
#   robot   10.77.1.1            semnav-mapping, and the simulator as the robot's software
#   ground  10.77.1.2 10.77.2.2  semnav-gateway, semnav-planning, semnav-relocalization
#   cloud   10.77.2.3            semnav-model-proxy
# A short simulated mission runs from the robot through the ground station; then the gateway's
# slow path crosses the ground -> cloud link (ResolveTarget answered by the cloud's model proxy,
# witnessed by the proxy's usage records), a second gateway with a token the cloud does not accept
# gets its model calls refused and keeps serving, and clients without a certificate, with a
# certificate of another CA, without TLS, without a token or with a wrong token are refused with
# the expected gRPC codes. Exit 77 (ctest SKIP) where namespaces cannot be made (not root, no
# iproute2, no CAP_SYS_ADMIN in a container).
# Usage: three_host_test.sh SOURCE_DIR BIN_DIR SHARED_DATA_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
bin_dir=$(cd "$2" && pwd)
shared_dir=$(cd "$3" && pwd)
skip() {
  echo "SKIP: $*"
  exit 77
}
[[ $(id -u) -eq 0 ]] || skip "needs root to create network namespaces (ip netns)"
command -v ip >/dev/null || skip "iproute2 (ip) is not installed"
command -v openssl >/dev/null || skip "openssl is not installed"
command -v node >/dev/null || skip "node is not installed (the ResolveTarget / GetUsage client)"

tag=$$
declare -A ns=([robot]=semnav-robot-$tag [ground]=semnav-ground-$tag [cloud]=semnav-cloud-$tag)
work=$(mktemp -d /tmp/semnav-three-hosts.XXXXXX)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  # `ip netns exec` forks: the services are its children, and SIGTERM to it left all six running
  # after ctest ended. Every process inside the test's namespaces is ours: stop them all.
  local inside=()
  for host in "${!ns[@]}"; do inside+=($(ip netns pids "${ns[$host]}" 2>/dev/null || true)); done
  ((${#inside[@]})) && kill -TERM "${inside[@]}" 2>/dev/null || true
  for _ in $(seq 50); do
    local alive=0
    for pid in "${inside[@]}"; do if kill -0 "$pid" 2>/dev/null; then alive=1; fi; done
    ((alive)) || break
    sleep 0.1
  done
  ((${#inside[@]})) && kill -KILL "${inside[@]}" 2>/dev/null || true
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  for host in "${!ns[@]}"; do
    ip netns del "${ns[$host]}" 2>/dev/null || true
    rm -rf "/etc/netns/${ns[$host]}"
  done
  rm -rf "$work"
}
trap cleanup EXIT
ip netns add "${ns[robot]}" 2>/dev/null || skip "cannot create network namespaces here (ip netns add failed)"
ip netns add "${ns[ground]}"
ip netns add "${ns[cloud]}"
in_ns() {
  local host=$1
  shift
  ip netns exec "${ns[$host]}" "$@"
}
in_ns robot true 2>/dev/null || skip "cannot enter network namespaces here (ip netns exec failed)"

# --- network: robot <-> ground on 10.77.1.0/24, ground <-> cloud on 10.77.2.0/24 ---------------
ip link add "sr$tag" netns "${ns[robot]}" type veth peer name "sg$tag" netns "${ns[ground]}" 2>/dev/null ||
  skip "cannot create veth pairs here (ip link add type veth failed)"
ip link add "tg$tag" netns "${ns[ground]}" type veth peer name "tc$tag" netns "${ns[cloud]}"
in_ns robot ip addr add 10.77.1.1/24 dev "sr$tag"
in_ns ground ip addr add 10.77.1.2/24 dev "sg$tag"
in_ns ground ip addr add 10.77.2.2/24 dev "tg$tag"
in_ns cloud ip addr add 10.77.2.3/24 dev "tc$tag"
for host in robot ground cloud; do in_ns "$host" ip link set lo up; done
in_ns robot ip link set "sr$tag" up
in_ns ground ip link set "sg$tag" up
in_ns ground ip link set "tg$tag" up
in_ns cloud ip link set "tc$tag" up
# Host names as each host's /etc/hosts knows them (ip netns exec mounts /etc/netns/<ns>/hosts).
declare -A hosts_file=(
  [robot]="10.77.1.1 robot
10.77.1.2 ground-station"
  [ground]="10.77.1.1 robot
10.77.1.2 ground-station
10.77.2.3 cloud"
  [cloud]="10.77.2.2 ground-station
10.77.2.3 cloud")
for host in robot ground cloud; do
  mkdir -p "/etc/netns/${ns[$host]}" 2>/dev/null || skip "cannot write /etc/netns (per-namespace /etc/hosts)"
  printf '127.0.0.1 localhost\n%s\n' "${hosts_file[$host]}" >"/etc/netns/${ns[$host]}/hosts"
done

# --- certificates and tokens, laid out per host as /etc/semnav expects --------------------------
pki=$work/pki
"$source_dir/tests/deploy/make_test_pki.sh" "$pki" robot=DNS:robot,IP:10.77.1.1 \
  ground=DNS:ground-station,IP:10.77.1.2,IP:10.77.2.2 cloud=DNS:cloud,IP:10.77.2.3
"$source_dir/tests/deploy/make_test_pki.sh" "$work/rogue" intruder=DNS:robot
robot_token=robot-$(openssl rand -hex 16)
station_token=station-$(openssl rand -hex 16)
declare -A accepted=([robot]="$robot_token $station_token" [ground]="$robot_token $station_token"
                     [cloud]="$station_token")
declare -A identity=([robot]=$robot_token [ground]=$station_token [cloud]=$station_token)
secret_file() {  # path content: a 0600 file, as the services require for tokens
  (umask 077 && printf '%s\n' $2 >"$1")
}
for host in robot ground cloud; do
  etc=$work/$host/etc/semnav
  mkdir -p "$etc/tls" "$etc/tokens" "$work/$host/var"
  cp "$pki/ca.crt" "$etc/tls/ca.crt"
  cp "$pki/$host.crt" "$etc/tls/host.crt"
  cp -p "$pki/$host.key" "$etc/tls/host.key"
  secret_file "$etc/tokens/accepted" "${accepted[$host]}"
  secret_file "$etc/tokens/client.token" "${identity[$host]}"
done
secret_file "$work/wrong.token" "not-$robot_token"

# The shipped config with this host's folders in place of /etc/semnav and /var/lib/semnav.
localize() {  # host config-name
  sed -e "s|/etc/semnav/|$work/$1/etc/semnav/|g" -e "s|/var/lib/semnav|$work/$1/var|g" \
    -e "s|/usr/local/share/semnav/lexicon.tsv|$source_dir/services/common/lexicon/lexicon.tsv|g" \
    -e "s|/usr/local/share/semnav/object-priors|$shared_dir/object-priors|g" \
    "$source_dir/deploy/systemd/etc/semnav/$2.yaml" >"$work/$1/etc/semnav/$2.yaml"
}
start() {  # host service
  localize "$1" "$2"
  in_ns "$1" "$bin_dir/semnav-$2" --config "$work/$1/etc/semnav/$2.yaml" \
    >"$work/$1/$2.out" 2>"$work/$1/$2.err" &
  pids+=($!)
}
start robot mapping
start ground planning
start ground gateway
start ground relocalization
start cloud model-proxy

# `semnav probe` from a host with that host's certificate and token, unless flags override them.
probe() {  # from-host address health-service [extra flags...]
  local from=$1 address=$2 service=$3
  shift 3
  local etc=$work/$from/etc/semnav
  in_ns "$from" "$bin_dir/semnav" probe --addr "$address" --service "$service" --timeout_s 2 \
    --ca_file "$etc/tls/ca.crt" --cert_file "$etc/tls/host.crt" --key_file "$etc/tls/host.key" \
    --token_file "$etc/tokens/client.token" "$@"
}
wait_serving() {  # from-host address health-service
  for _ in $(seq 1 40); do
    probe "$@" >/dev/null 2>&1 && return 0
    sleep 0.5
  done
  echo "FAIL: $2 ($3) never became SERVING from $1"
  tail -n 20 "$work"/*/*.err
  exit 1
}
wait_serving robot robot:50051 semnav.mapping.v1.MappingService
wait_serving robot ground-station:50050 semnav.reasoning.v1.RobotSessionService
wait_serving robot ground-station:50052 semnav.planning.v1.PlanningService
wait_serving robot ground-station:50053 semnav.relocalization.v1.RelocalizationService
wait_serving ground cloud:50054 semnav.modelproxy.v1.ModelProxyService
echo "three hosts up: robot 10.77.1.1, ground station 10.77.1.2/10.77.2.2, cloud 10.77.2.3 (mTLS + tokens)"

# --- a short mission: the robot's simulator streams to its mapping and talks to the ground -----
robot_etc=$work/robot/etc/semnav
tls="{ca_file: $robot_etc/tls/ca.crt, cert_file: $robot_etc/tls/host.crt, key_file: $robot_etc/tls/host.key}"
auth="{token_file: $robot_etc/tokens/client.token}"
cat >"$work/robot/remote.yaml" <<EOF
gateway: {address: "ground-station:50050", tls: $tls, auth: $auth}
mapping: {address: "robot:50051", tls: $tls, auth: $auth}
planning: {address: "ground-station:50052", tls: $tls, auth: $auth}
EOF
if ! in_ns robot timeout 90 "$bin_dir/semnav-sim-demo" --remote "$work/robot/remote.yaml" \
  --out "$work/robot/report" >"$work/mission.out" 2>&1; then
  echo "FAIL: the mission did not succeed across the three hosts:"
  cat "$work/mission.out"
  tail -n 20 "$work"/*/*.err
  exit 1
fi
grep '^SUCCESS' "$work/mission.out"

# --- ground -> cloud: the gateway's slow path through the cloud's model proxy --------------------
ground_etc=$work/ground/etc/semnav
call() {  # address proto-file service method request-json: a unary call from the ground station
  in_ns ground env NODE_PATH="$source_dir/node_modules" node "$source_dir/tests/deploy/grpc_call.js" \
    "$source_dir/protos" "$2" "$3" "$4" "$5" "$1" "$ground_etc/tls/ca.crt" "$ground_etc/tls/host.crt" \
    "$ground_etc/tls/host.key" "$ground_etc/tokens/client.token"
}
resolve() {  # gateway-address robot-id: resolve a target the scene graph lacks, beside an object it has
  call "$1" semnav/reasoning/v1/operator.proto semnav.reasoning.v1.OperatorService ResolveTarget \
    "{\"robot_id\": \"$2\", \"text\": \"the purple umbrella near the $mission_target\", \"allow_slow_path\": true}"
}
resolve_grounded() {  # gateway-address robot-id: resolve once the gateway has the robot's scene graph
  local output
  for _ in $(seq 1 20); do
    if output=$(resolve "$1" "$2" 2>&1) && [[ $output == *'nothing to ground'* ]]; then
      sleep 0.5  # the gateway's mapping watch has not delivered a graph yet
      continue
    fi
    printf '%s\n' "$output"
    [[ $output == '{'* ]]
    return
  done
  printf '%s\n' "$output"
  return 1
}
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
mission_target=$(sed -n 's/.*instruction "find a \(.*\)" (gateway.*/\1/p' "$work/mission.out")
# The fast path finds no umbrella (no label match), so the slow path asks the cloud about the
# objects near the mission's target: grounded objects prove the robot's scene graph reached the
# ground station, the answer that the cloud answered the gateway.
if answer=$(resolve_grounded ground-station:50050 three-host-operator) &&
  [[ $answer =~ \"grounded_objects\":([1-9][0-9]*) ]]; then
  echo "ok: slow path over ground -> cloud answered (${BASH_REMATCH[1]} grounded objects): $answer"
else
  fail "the gateway's slow path did not get an answer from the cloud: $answer"
fi
# The cloud's own record: the call came from the gateway (its robot id metadata) and was answered.
usage=$(call cloud:50054 semnav/modelproxy/v1/modelproxy.proto semnav.modelproxy.v1.ModelProxyService GetUsage \
  '{"robot_id": "three-host-operator"}' 2>&1) || true
if [[ $usage =~ \"backend\":\"offline\",\"calls\":([1-9][0-9]*) ]]; then
  echo "ok: the cloud's model proxy answered ${BASH_REMATCH[1]} call(s) of the ground station's gateway"
else
  fail "the cloud's usage shows no answered gateway call: $usage"
fi

# The mission's task counted its model calls (text embedding, slow path) at the gateway.
tasks=$(in_ns ground "$bin_dir/semnavctl" task list --json --gateway-addr ground-station:50050 \
  --tls-ca "$ground_etc/tls/ca.crt" --tls-cert "$ground_etc/tls/host.crt" --tls-key "$ground_etc/tls/host.key" \
  --token-file "$ground_etc/tokens/client.token" 2>&1) || true
if [[ $tasks =~ \"model_calls\":([1-9][0-9]*) ]]; then
  echo "ok: semnavctl task list: the mission's task made ${BASH_REMATCH[1]} model call(s)"
else
  fail "the mission's task made no model calls: $tasks"
fi

# A second gateway presents a token the cloud does not accept (the robot's): refused, still serving.
sed '/^  model_proxy:/,/^  [a-z_]*:/ s|tokens/client.token|tokens/cloud-wrong.token|' \
  "$ground_etc/gateway.yaml" >"$ground_etc/gateway-wrong-cloud-token.yaml"
[[ $(grep -c cloud-wrong.token "$ground_etc/gateway-wrong-cloud-token.yaml") == 1 ]] ||
  { echo "FAIL: no model_proxy token_file in gateway.yaml"; exit 1; }
secret_file "$ground_etc/tokens/cloud-wrong.token" "$robot_token"
in_ns ground "$bin_dir/semnav-gateway" --config "$ground_etc/gateway-wrong-cloud-token.yaml" \
  --listen 10.77.1.2:50060 >"$work/ground/gateway-wrong.out" 2>"$work/ground/gateway-wrong.err" &
wrong_gateway=$!
pids+=("$wrong_gateway")
wait_serving ground ground-station:50060 semnav.reasoning.v1.OperatorService
if refusal=$(resolve_grounded ground-station:50060 three-host-wrong-token 2>&1); then
  fail "a gateway with a wrong cloud token got a model answer: $refusal"
elif [[ $refusal != UNAUTHENTICATED:* ]]; then
  fail "a gateway with a wrong cloud token: expected UNAUTHENTICATED from the cloud, got: $refusal"
elif ! kill -0 "$wrong_gateway" 2>/dev/null || ! probe ground ground-station:50060 \
  semnav.reasoning.v1.OperatorService >/dev/null; then
  fail "the gateway with a wrong cloud token stopped serving after the refusal"
else
  echo "ok: gateway with a wrong cloud token -> its model call refused ($refusal), gateway still SERVING"
fi

# --- refusals -------------------------------------------------------------------------------------
expect_refused() {  # code description probe-args...
  local code=$1 what=$2
  shift 2
  local output
  if output=$(probe "$@" 2>&1); then
    fail "$what was admitted: $output"
  elif [[ $output != *"semnav probe: $code:"* ]]; then
    fail "$what: expected $code, got: $output"
  else
    echo "ok: $what -> $code"
  fi
}
for target in "robot ground-station:50050 semnav.reasoning.v1.OperatorService" \
              "ground cloud:50054 semnav.modelproxy.v1.ModelProxyService" \
              "ground robot:50051 semnav.mapping.v1.MappingService"; do
  read -r from address service <<<"$target"
  expect_refused UNAVAILABLE "$from -> $address without a client certificate" \
    "$from" "$address" "$service" --cert_file "" --key_file ""
  expect_refused UNAVAILABLE "$from -> $address with a certificate of another CA" \
    "$from" "$address" "$service" --cert_file "$work/rogue/intruder.crt" --key_file "$work/rogue/intruder.key"
  expect_refused UNAVAILABLE "$from -> $address in plaintext" "$from" "$address" "$service" \
    --ca_file "" --cert_file "" --key_file ""
  expect_refused UNAUTHENTICATED "$from -> $address without a token" "$from" "$address" "$service" --token_file ""
  expect_refused UNAUTHENTICATED "$from -> $address with a wrong token" "$from" "$address" "$service" \
    --token_file "$work/wrong.token"
done
# The robot's token is not accepted by the cloud, only the station's.
expect_refused UNAUTHENTICATED "cloud token list without the robot's token" ground cloud:50054 \
  semnav.modelproxy.v1.ModelProxyService --token_file "$work/robot/etc/semnav/tokens/client.token"
((failures == 0)) || exit 1
echo "PASS: mission across three hosts with mTLS and tokens; the gateway's model calls answered by the cloud"
echo "      and refused with a wrong token; 16 unauthorized clients refused"
