#!/usr/bin/python3
"""Checks the deployment files against the build: docker/, deploy/compose.yaml, deploy/k8s/,
deploy/systemd/. No container engine or cluster is needed: every YAML parses, every binary an
image, manifest or unit runs is built, every config is accepted by its binary (it is started with
it, certificates and tokens generated), and every port and health service name a probe uses is
the one the running binary serves.

Usage: check_deploy_files.py SOURCE_DIR BIN_DIR SHARED_DATA_DIR
"""
import functools
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

import yaml

SOURCE, BIN, SHARED = (os.path.abspath(p) for p in sys.argv[1:4])
DEPLOY = os.path.join(SOURCE, "deploy")
SERVICES = ["gateway", "mapping", "planning", "relocalization", "model-proxy"]
# The gateway's client sections and the service each one dials.
GATEWAY_PEERS = {"mapping": "mapping", "planning": "planning", "model_proxy": "model-proxy"}


def binary_of(service):
    """The binary a config, image or unit named after a service runs."""
    return "semnav-" + service


def read(path):
    with open(path) as f:
        return f.read()


def load_yaml(path):
    return list(yaml.safe_load_all(read(path)))


def listen_port(config_path):
    return int(load_yaml(config_path)[0]["server"]["listen"].rsplit(":", 1)[1])


def gateway_section(config_path):
    return load_yaml(config_path)[0]["gateway"]


def install_deps_packages():
    text = read(os.path.join(DEPLOY, "install-deps.sh"))
    body = re.search(r"packages=\((.*?)\n\)", text, re.S).group(1)
    return {w for line in body.splitlines() for w in line.split("#")[0].split()}


class Dockerfile:
    """The instructions of a Dockerfile, continuation lines joined, split into stages."""

    def __init__(self, path):
        text = read(path).replace("\\\n", " ")
        self.stages = []
        for line in text.splitlines():
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            keyword, _, rest = line.partition(" ")
            if keyword == "FROM":
                self.stages.append([])
            self.stages[-1].append((keyword, rest.strip()))
        self.runtime = self.stages[-1]

    def froms(self):
        return [stage[0][1] for stage in self.stages]

    def runtime_all(self, keyword):
        return [rest for k, rest in self.runtime if k == keyword]

    def runtime_one(self, keyword):
        (value,) = self.runtime_all(keyword)
        return value


def shipped_from_shared_data(dockerfile, path):
    """The file under SHARED that `path` in the image is copied from, or None."""
    for args in dockerfile.runtime_all("COPY"):
        parts = args.split()
        if parts[0] == "--from=shared-data" and path.startswith(parts[-1].rstrip("/") + "/"):
            return os.path.join(SHARED, parts[1], path[len(parts[-1].rstrip("/")) + 1:])
    return None


def apt_packages(run_args):
    match = re.search(r"apt-get install -y --no-install-recommends (.*?)(&&|$)", run_args)
    return match.group(1).split()


class Pki:
    """A CA, one host certificate and token files laid out as deploy/systemd/etc/semnav expects."""

    def __init__(self, root):
        self.etc = os.path.join(root, "etc", "semnav")
        tls = os.path.join(self.etc, "tls")
        subprocess.run([os.path.join(SOURCE, "tests/deploy/make_test_pki.sh"), tls,
                        "host=DNS:ground-station,DNS:robot,IP:127.0.0.1"], check=True)
        tokens = os.path.join(self.etc, "tokens")
        os.makedirs(tokens)
        for name, content in (("accepted", "token-of-a-robot\ntoken-of-the-station\n"),
                              ("client.token", "token-of-the-station\n")):
            path = os.path.join(tokens, name)
            with open(path, "w") as f:
                f.write(content)
            os.chmod(path, 0o600)
        self.var = os.path.join(root, "var")
        os.makedirs(self.var)

    def localize(self, text):
        """Rewrites the installed paths of a config or command to this test's files."""
        return (text.replace("/etc/semnav/", self.etc + "/")
                .replace("/var/lib/semnav", self.var)
                .replace("/usr/local/share/semnav/lexicon.tsv",
                         os.path.join(SOURCE, "services/common/lexicon/lexicon.tsv"))
                .replace("/usr/local/share/semnav/object-priors", os.path.join(SHARED, "object-priors")))


class RunningService:
    """A binary started with a localized config on a free loopback port."""

    def __init__(self, binary, config_path, pki, workdir):
        localized = os.path.join(workdir, os.path.basename(config_path))
        with open(localized, "w") as f:
            f.write(pki.localize(read(config_path)))
        self.process = subprocess.Popen(
            [os.path.join(BIN, binary), "--config", localized, "--listen", "127.0.0.1:0"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        if " serving on " not in line:
            self.process.kill()
            error = self.process.stderr.read()
            self.process.wait()
            self.process.stdout.close()
            self.process.stderr.close()
            raise AssertionError(f"{binary} --config {config_path}: {line}{error}")
        self.port = int(line.strip().rsplit(":", 1)[1])

    def stop(self):
        self.process.send_signal(signal.SIGTERM)
        code = self.process.wait(timeout=15)
        self.process.stdout.close()
        self.process.stderr.close()
        return code


def probe(args, port):
    """Runs a `semnav probe` command line with its --addr pointed at `port`."""
    args = list(args)
    addr = args.index("--addr") + 1
    args[addr] = "127.0.0.1:%d" % port
    return subprocess.run([os.path.join(BIN, "semnav"), "probe"] + args, capture_output=True, text=True, timeout=15)


class DeployFilesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="semnav-deploy-check-")
        cls.pki = Pki(cls.tmp)
        cls.k8s_docs = {}
        for name in os.listdir(os.path.join(DEPLOY, "k8s")):
            if name.endswith(".yaml"):
                cls.k8s_docs[name] = load_yaml(os.path.join(DEPLOY, "k8s", name))
        cls.compose = load_yaml(os.path.join(DEPLOY, "compose.yaml"))[0]
        cls.dockerfiles = {s: Dockerfile(os.path.join(SOURCE, "docker", s + ".Dockerfile")) for s in SERVICES}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def start_and_probe(self, binary, config, probes):
        """Starts `binary` with `config`, runs each `semnav probe` argument list against it."""
        service = RunningService(binary, config, self.pki, self.tmp)
        try:
            for args in probes:
                result = probe(shlex.split(self.pki.localize(shlex.join(args))), service.port)
                self.assertEqual(result.stdout.strip(), "SERVING",
                                 f"{binary} with {config}: probe {args} -> {result.stdout}{result.stderr}")
        finally:
            self.assertEqual(service.stop(), 0, f"{binary} did not stop cleanly")

    def deployments(self):
        for docs in self.k8s_docs.values():
            for doc in docs:
                if doc and doc.get("kind") == "Deployment":
                    yield doc

    # --- every file parses -------------------------------------------------------------------

    def test_every_yaml_parses(self):
        paths = [os.path.join(DEPLOY, "compose.yaml"), os.path.join(DEPLOY, "local.yaml")]
        for folder in ("k8s", "k8s/config", "systemd/etc/semnav"):
            paths += [os.path.join(DEPLOY, folder, n) for n in sorted(os.listdir(os.path.join(DEPLOY, folder)))
                      if n.endswith(".yaml")]
        for path in paths:
            with self.subTest(path=path):
                self.assertTrue(all(doc is not None for doc in load_yaml(path)), "empty document")

    # --- docker/ -----------------------------------------------------------------------------

    def test_images_build_on_bookworm_from_the_install_deps_packages(self):
        known = install_deps_packages()
        for service, dockerfile in self.dockerfiles.items():
            with self.subTest(image=service):
                self.assertEqual(dockerfile.froms(), ["debian:bookworm AS build", "debian:bookworm"])
                build_run = next(r for k, r in dockerfile.stages[0] if k == "RUN")
                self.assertLessEqual(set(apt_packages(build_run)), known, "not in deploy/install-deps.sh")

    def test_runtime_stage_has_exactly_the_libraries_its_binaries_need(self):
        if shutil.which("dpkg") is None:
            self.skipTest("dpkg not available: cannot map libraries to packages")
        for service, dockerfile in self.dockerfiles.items():
            packages = set(apt_packages(dockerfile.runtime_all("RUN")[0]))
            with self.subTest(image=service):
                self.assertFalse([p for p in packages if p.endswith("-dev")], "-dev package in the runtime stage")
                needed = set()
                for binary in (binary_of(service), "semnav"):
                    needed |= self.packages_needed_by(os.path.join(BIN, binary))
                base = {"libc6", "libgcc-s1", "libstdc++6", "zlib1g"}
                self.assertLessEqual(needed - base, packages, "runtime libraries missing from the image")
                self.assertLessEqual(packages - needed, {"ca-certificates"}, "packages no binary needs")

    @functools.cache
    def packages_needed_by(self, path):
        elf = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
        libs = set(re.findall(r"\(NEEDED\).*\[(.*)\]", elf))
        resolved = dict(re.findall(r"^\s*(\S+) => (\S+)", subprocess.run(
            ["ldd", path], capture_output=True, text=True, check=True).stdout, re.M))
        real = [os.path.realpath(resolved[lib]) for lib in libs]
        # dpkg knows a file under the path its package installed it to (/lib or /usr/lib); one
        # query for all of them, as each scans the whole package database.
        owners = subprocess.run(["dpkg", "-S"] + real + [r.removeprefix("/usr") for r in real],
                                capture_output=True, text=True).stdout
        owner_of = {line.split(": ", 1)[1]: line.split(":")[0] for line in owners.splitlines()}
        packages = set()
        for lib, r in zip(libs, real):
            found = owner_of.get(r) or owner_of.get(r.removeprefix("/usr"))
            self.assertTrue(found, f"{lib} of {path} is not from a Debian package")
            packages.add(found)
        return packages

    def test_images_copy_and_run_binaries_the_build_produces(self):
        for service, dockerfile in self.dockerfiles.items():
            with self.subTest(image=service):
                build_run = [r for k, r in dockerfile.stages[0] if k == "RUN"][-1]
                targets = build_run.split("--target", 1)[1].split()
                copied = []
                for args in dockerfile.runtime_all("COPY"):
                    parts = args.split()
                    if parts[0] == "--from=build":
                        copied += [os.path.basename(p) for p in parts[1:-1]]
                        self.assertEqual(parts[-1], "/usr/local/bin/")
                    elif parts[0] == "--from=shared-data":
                        self.assertTrue(os.path.isdir(os.path.join(SHARED, parts[1])), parts[1])
                    else:
                        self.assertTrue(os.path.exists(os.path.join(SOURCE, parts[0])), parts[0])
                self.assertEqual(sorted(copied), sorted(targets), "copied binaries != built targets")
                for binary in copied:
                    self.assertTrue(os.access(os.path.join(BIN, binary), os.X_OK), f"{binary} is not built")
                self.assertEqual(dockerfile.runtime_one("ENTRYPOINT"), f'["{binary_of(service)}"]')
                self.assertNotIn(dockerfile.runtime_one("USER"), ("root", "0"))

    def test_image_default_config_serves_on_the_exposed_port_and_health_service(self):
        for service, dockerfile in self.dockerfiles.items():
            with self.subTest(image=service):
                config_in_image = yaml.safe_load(dockerfile.runtime_one("CMD"))[1]
                copies = dict(reversed(c.split()) for c in dockerfile.runtime_all("COPY") if c.startswith("deploy/"))
                config = os.path.join(SOURCE, copies[config_in_image])
                port = int(dockerfile.runtime_one("EXPOSE"))
                self.assertEqual(listen_port(config), port)
                health = yaml.safe_load(dockerfile.runtime_one("HEALTHCHECK").split("CMD", 1)[1])
                self.assertEqual(health[:2], ["semnav", "probe"])
                self.assertEqual(health[health.index("--addr") + 1], f"127.0.0.1:{port}")
                self.start_and_probe(binary_of(service), config, [health[2:]])

    def test_probe_exits_nonzero_with_the_code_of_a_failed_check(self):
        service = RunningService("semnav-planning", os.path.join(DEPLOY, "k8s/config/planning.yaml"), self.pki, self.tmp)
        try:
            unknown = probe(["--addr", "x", "--service", "semnav.planning.v1.NoSuchService"], service.port)
            self.assertEqual((unknown.returncode, unknown.stderr.split(":")[:2]), (1, ["semnav probe", " NOT_FOUND"]))
            token = probe(["--addr", "x", "--token_file", os.path.join(self.pki.etc, "tokens/client.token")],
                          service.port)
            self.assertEqual(token.stdout.strip(), "SERVING")  # a token to a server without auth is ignored
        finally:
            self.assertEqual(service.stop(), 0)
        self.assertEqual(probe(["--addr", "x", "--timeout_s", "soon"], 1).returncode, 2)

    # --- deploy/k8s --------------------------------------------------------------------------

    def test_kustomization_lists_existing_files_and_generates_the_mounted_configmap(self):
        kustomization = self.k8s_docs["kustomization.yaml"][0]
        for resource in kustomization["resources"]:
            self.assertIn(resource, self.k8s_docs)
        (generator,) = kustomization["configMapGenerator"]
        for path in generator["files"]:
            self.assertTrue(os.path.isfile(os.path.join(DEPLOY, "k8s", path)), path)
        images = {i["name"] for i in kustomization["images"]}
        for deployment in self.deployments():
            volumes = {v["name"]: v for v in deployment["spec"]["template"]["spec"]["volumes"]}
            self.assertEqual(volumes["config"]["configMap"]["name"], generator["name"])
            (container,) = deployment["spec"]["template"]["spec"]["containers"]
            self.assertIn(container["image"], images)

    def test_deployments_run_built_binaries_with_their_config_ports_and_health_services(self):
        deployments = list(self.deployments())
        self.assertEqual(sorted(d["metadata"]["name"] for d in deployments), sorted(SERVICES))
        services = {d["metadata"]["name"]: d for docs in self.k8s_docs.values() for d in docs
                    if d and d.get("kind") == "Service"}
        for deployment in deployments:
            name = deployment["metadata"]["name"]
            with self.subTest(deployment=name):
                (container,) = deployment["spec"]["template"]["spec"]["containers"]
                dockerfile = self.dockerfiles[name]
                self.assertEqual(container["image"], binary_of(name))
                self.assertTrue(os.access(os.path.join(BIN, container["image"]), os.X_OK))
                self.assertEqual(container["args"][0], "--config")
                config = os.path.join(DEPLOY, "k8s", "config", os.path.basename(container["args"][1]))
                port = listen_port(config)
                self.assertEqual(container["ports"][0]["containerPort"], port)
                self.assertEqual(int(dockerfile.runtime_one("EXPOSE")), port)
                self.assertEqual(services[name]["spec"]["ports"][0]["port"], port)
                for kind in ("startupProbe", "readinessProbe", "livenessProbe"):
                    self.assertEqual(container[kind]["grpc"]["port"], port, kind)
                resources = container["resources"]
                self.assertTrue(resources["requests"]["cpu"] and resources["limits"]["memory"])
                health_service = container["readinessProbe"]["grpc"]["service"]
                self.start_and_probe(container["image"], config,
                                     [["--addr", "x", "--service", health_service]])

    def test_model_keys_secret_matches_what_the_model_proxy_reads(self):
        (secret,) = self.k8s_docs["secret-model-keys.example.yaml"]
        (deployment,) = [d for d in self.deployments() if d["metadata"]["name"] == "model-proxy"]
        (container,) = deployment["spec"]["template"]["spec"]["containers"]
        self.assertEqual(container["envFrom"][0]["secretRef"]["name"], secret["metadata"]["name"])
        config = load_yaml(os.path.join(DEPLOY, "k8s/config/model-proxy.yaml"))[0]
        key_envs = {b["api_key_env"] for b in config["modelproxy"]["backends"].values() if "api_key_env" in b}
        self.assertEqual(set(secret["stringData"]), key_envs)

    # --- the gateway's peers (model proxy included) and its commonsense prior ---------------

    def test_cluster_gateway_dials_each_peer_service_on_its_listen_port(self):
        services = {d["metadata"]["name"]: d for docs in self.k8s_docs.values() for d in docs
                    if d and d.get("kind") == "Service"}
        gateway = gateway_section(os.path.join(DEPLOY, "k8s/config/gateway.yaml"))
        for section, peer in GATEWAY_PEERS.items():
            with self.subTest(section=section):
                host, port = gateway[section]["address"].rsplit(":", 1)
                self.assertEqual(host, peer, "not the peer's Service name")
                self.assertEqual(services[host]["spec"]["selector"], {"app.kubernetes.io/name": peer})
                self.assertEqual(services[host]["spec"]["ports"][0]["port"], int(port))
                self.assertEqual(listen_port(os.path.join(DEPLOY, "k8s/config", peer + ".yaml")), int(port))

    def test_host_gateway_dials_each_peer_with_the_certificate_and_token_it_requires(self):
        # systemd and compose share these configs; the model proxy is the cloud host's.
        hosts = {"mapping": "robot", "planning": "ground-station", "model_proxy": "cloud"}
        etc = os.path.join(DEPLOY, "systemd/etc/semnav")
        gateway = gateway_section(os.path.join(etc, "gateway.yaml"))
        compose_configs = {s["image"].split(":")[0]: s["command"][1] for s in self.compose["services"].values()}
        for section, peer in GATEWAY_PEERS.items():
            with self.subTest(section=section):
                client = gateway[section]
                host, port = client["address"].rsplit(":", 1)
                self.assertEqual(host, hosts[section])
                self.assertEqual(listen_port(os.path.join(etc, peer + ".yaml")), int(port))
                server = load_yaml(os.path.join(etc, peer + ".yaml"))[0]["server"]
                if "client_ca_file" in server.get("tls", {}):
                    self.assertEqual(set(client.get("tls", {})), {"ca_file", "cert_file", "key_file"}, "mTLS client")
                if "auth" in server:
                    self.assertEqual(client.get("auth"), {"token_file": "/etc/semnav/tokens/client.token"}, "token")
                if binary_of(peer) in compose_configs:  # compose runs the peer from the same config
                    self.assertEqual(compose_configs[binary_of(peer)], f"/etc/semnav/{peer}.yaml")

    def test_gateway_prior_is_the_model_proxy_data_shipped_beside_it(self):
        image = self.dockerfiles["gateway"]
        copies = dict(reversed(c.split()) for c in image.runtime_all("COPY") if c.startswith("deploy/"))
        image_config = os.path.join(SOURCE, copies[yaml.safe_load(image.runtime_one("CMD"))[1]])
        layouts = {"image and cluster": (image_config, os.path.join(DEPLOY, "k8s/config/model-proxy.yaml")),
                   "hosts": (os.path.join(DEPLOY, "systemd/etc/semnav/gateway.yaml"),
                             os.path.join(DEPLOY, "systemd/etc/semnav/model-proxy.yaml"))}
        for layout, (gateway_config, proxy_config) in layouts.items():
            with self.subTest(layout=layout):
                prior = gateway_section(gateway_config)["prior_path"]
                data_dir = load_yaml(proxy_config)[0]["modelproxy"]["offline"]["data_dir"]
                self.assertEqual(os.path.dirname(prior), data_dir, "not the model proxy's offline data")
                self.assertTrue(os.path.isfile(self.pki.localize(prior)), prior)
        image_prior = gateway_section(image_config)["prior_path"]
        source = shipped_from_shared_data(image, image_prior)
        self.assertTrue(source and os.path.isfile(source), f"{image_prior} is not copied into the gateway image")

    # --- deploy/compose.yaml and deploy/systemd (same configs under /etc/semnav) ------------

    def test_compose_services_run_built_binaries_and_their_healthchecks_pass(self):
        for name, service in self.compose["services"].items():
            with self.subTest(service=name):
                binary = service["image"].split(":")[0]
                self.assertIn(binary, [binary_of(s) for s in SERVICES])
                self.assertEqual(service["command"][0], "--config")
                config = os.path.join(DEPLOY, "systemd", service["command"][1].lstrip("/"))
                health = service["healthcheck"]["test"]
                self.assertEqual(health[:3], ["CMD", "semnav", "probe"])
                self.assertEqual(health[health.index("--addr") + 1], f"127.0.0.1:{listen_port(config)}")
                self.start_and_probe(binary, config, [health[3:]])

    def test_systemd_units_verify_and_each_instance_has_a_binary_and_config(self):
        units = os.path.join(DEPLOY, "systemd")
        instances = set()
        for target in ("semnav-ground-station.target", "semnav-robot.target"):
            wants = re.search(r"^Wants=(.*)$", read(os.path.join(units, target)), re.M).group(1)
            instances |= set(re.findall(r"semnav@([\w-]+)\.service", wants))
        self.assertEqual(instances, set(SERVICES))
        health_services = {d["metadata"]["name"]: d["spec"]["template"]["spec"]["containers"][0]["readinessProbe"]
                           ["grpc"]["service"] for d in self.deployments()}
        for instance in sorted(instances):
            with self.subTest(instance=instance):
                self.start_and_probe(binary_of(instance), os.path.join(units, "etc/semnav", instance + ".yaml"), [[
                    "--addr", "x", "--service", health_services[instance], "--ca_file", "/etc/semnav/tls/ca.crt",
                    "--cert_file", "/etc/semnav/tls/host.crt", "--key_file", "/etc/semnav/tls/host.key",
                    "--server_name", "robot", "--token_file", "/etc/semnav/tokens/client.token"]])
        unit_text = read(os.path.join(units, "semnav@.service"))
        self.assertIn("ExecStart=/usr/local/bin/semnav-%i --config /etc/semnav/%i.yaml", unit_text)
        if shutil.which("systemd-analyze") is None:
            self.skipTest("systemd-analyze not available; the units were only parsed")
        # verify resolves ExecStart, so the copies run the build's binaries.
        verify_dir = os.path.join(self.tmp, "units")
        os.makedirs(verify_dir)
        for name in os.listdir(units):
            if name.endswith((".service", ".target")):
                text = read(os.path.join(units, name)).replace("/usr/local/bin/", BIN + "/")
                with open(os.path.join(verify_dir, name), "w") as f:
                    f.write(text)
        for instance in sorted(instances):
            os.symlink("semnav@.service", os.path.join(verify_dir, f"semnav@{instance}.service"))
        names = sorted(n for n in os.listdir(verify_dir) if n != "semnav@.service")
        result = subprocess.run(["systemd-analyze", "verify", "--man=no"] + names, cwd=verify_dir,
                                capture_output=True, text=True,
                                env=dict(os.environ, SYSTEMD_UNIT_PATH=verify_dir + ":"))
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertNotIn(verify_dir, result.stderr, result.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
