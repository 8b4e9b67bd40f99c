// The real server (grainlab::server::serve with the real engine) with every ServeOptions field
// on the command line, so the integration tests can set small limits and a free port.
#include <cstdlib>
#include <iostream>
#include <string>

#include "grainlab/server/serve.hpp"

int main(int argc, char** argv) {
  grainlab::server::ServeOptions o;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--resume-interrupted") {
      o.resumeInterrupted = true;
      continue;
    }
    if (k + 1 >= argc) {
      std::cerr << "grainlab_test_server: " << arg << " needs a value\n";
      return 2;
    }
    const std::string value = argv[++k];
    if (arg == "--host") o.host = value;
    else if (arg == "--port") o.port = static_cast<unsigned short>(std::stoi(value));
    else if (arg == "--db") o.db = value;
    else if (arg == "--web") o.webRoot = value;
    else if (arg == "--max-concurrent") o.maxConcurrentRuns = std::stoi(value);
    else if (arg == "--max-queued") o.maxQueuedRuns = std::stoi(value);
    else if (arg == "--max-particles") o.maxParticles = std::stoi(value);
    else if (arg == "--max-body") o.maxBodyBytes = std::stoull(value);
    else if (arg == "--max-run-seconds") o.maxRunSeconds = std::stod(value);
    else if (arg == "--io-threads") o.ioThreads = std::stoi(value);
    else if (arg == "--fps") o.framesPerSecond = std::stod(value);
    else if (arg == "--replay-every") o.replayFrameEvery = std::stoi(value);
    else if (arg == "--token-file") o.tokenFile = value;
    else if (arg == "--read-only-token-file") o.readOnlyTokenFile = value;
    else if (arg == "--allowed-hosts") o.allowedHosts = {value};
    else if (arg == "--allowed-origins") o.allowedOrigins = {value};
    else if (arg == "--import-root") o.importRoot = value;
    else {
      std::cerr << "grainlab_test_server: unknown option " << arg << "\n";
      return 2;
    }
  }
  return grainlab::server::serve(o);
}
