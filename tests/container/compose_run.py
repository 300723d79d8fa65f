#!/usr/bin/python3
"""Runs one service of docker/compose.yaml with `podman run`.

There is no `docker compose` on the project's machines, so the container
test starts the compose file's services one at a time with this, the way
`docker compose up SERVICE` would: the same image, host network,
environment, volumes, entrypoint and command, read from the file itself so
the test exercises the file as users get it. It understands the keys the
file uses and refuses any other, rather than run something different from
what compose would.

  compose_run.py COMPOSE_FILE SERVICE [--project NAME] [--detach] [-- EXTRA PODMAN RUN ARGS]

Containers are named <project>_<service>, named volumes <project>_<volume>
(as compose names them); the project defaults to the file's `name`. Values
are interpolated from the environment (${VAR}, ${VAR:-default}, $$).
Exits with podman's exit code.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys

import yaml

SUPPORTED = {"image", "network_mode", "volumes", "environment", "entrypoint", "command", "depends_on", "profiles"}
VARIABLE = re.compile(r"\$(?:\$|\{(\w+)(?::-([^}]*))?\}|(\w+))")


def interpolate(value):
    """Compose's variable substitution, applied to every string in the file."""
    if isinstance(value, str):
        def substitute(match):
            if match.group(0) == "$$":
                return "$"
            name = match.group(1) or match.group(3)
            default = match.group(2)
            found = os.environ.get(name)
            if default is not None and not found:
                return default
            return found or ""
        return VARIABLE.sub(substitute, value)
    if isinstance(value, list):
        return [interpolate(v) for v in value]
    if isinstance(value, dict):
        return {k: interpolate(v) for k, v in value.items()}
    return value


def environment_items(environment):
    if isinstance(environment, dict):
        return [f"{k}={'' if v is None else v}" for k, v in environment.items()]
    return list(environment or [])


def command_list(value):
    """Compose takes a list as it is and splits a string as a shell would."""
    return value if isinstance(value, list) else shlex.split(value)


def podman_arguments(compose, service_name, project, detach, extra):
    services = compose.get("services", {})
    if service_name not in services:
        sys.exit(f"compose_run: no service {service_name!r} in the file (services: {', '.join(services)})")
    service = services[service_name]
    unknown = set(service) - SUPPORTED
    if unknown:
        sys.exit(f"compose_run: service {service_name}: keys {sorted(unknown)} are not translated to podman run")
    if "image" not in service:
        sys.exit(f"compose_run: service {service_name} has no image")
    named_volumes = set((compose.get("volumes") or {}).keys())

    arguments = ["run", "--name", f"{project}_{service_name}"]
    arguments.append("--detach" if detach else "--rm")
    if "network_mode" in service:
        arguments += ["--network", service["network_mode"]]
    for item in environment_items(service.get("environment")):
        arguments += ["--env", item]
    for volume in service.get("volumes", []):
        source, _, target = volume.partition(":")
        if source in named_volumes:
            source = f"{project}_{source}"
        arguments += ["--volume", f"{source}:{target}"]
    entrypoint = service.get("entrypoint")
    if entrypoint is not None:
        arguments += ["--entrypoint", json.dumps(command_list(entrypoint))]
    arguments += extra
    arguments.append(service["image"])
    if service.get("command") is not None:
        arguments += command_list(service["command"])
    return arguments


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("compose_file")
    parser.add_argument("service")
    parser.add_argument("--project", help="default: the file's name")
    parser.add_argument("--detach", action="store_true", help="start it in the background (else run it and remove it)")
    parser.add_argument("extra", nargs="*", help="more podman run options, after --")
    options = parser.parse_args()
    with open(options.compose_file, encoding="utf-8") as file:
        compose = interpolate(yaml.safe_load(file))
    project = options.project or compose.get("name") or "compose"
    arguments = podman_arguments(compose, options.service, project, options.detach, options.extra)
    print("+ podman " + " ".join(arguments), file=sys.stderr, flush=True)
    return subprocess.run(["podman", *arguments], check=False).returncode


if __name__ == "__main__":
    sys.exit(main())
