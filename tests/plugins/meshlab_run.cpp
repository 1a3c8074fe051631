#include "meshlab_run.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace {

std::string quote(const std::string &s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

std::string makeTempDir() {
    char pattern[] = "/tmp/voxelfair-test-XXXXXX";
    const char *dir = mkdtemp(pattern);
    if (dir == nullptr)
        throw std::runtime_error("mkdtemp failed");
    return dir;
}

MeshlabRun runMeshlabServer(const std::vector<std::string> &args, const std::map<std::string, std::string> &env) {
    const std::string home = makeTempDir();
    std::string command = "env XDG_CONFIG_HOME=" + quote(home) + " XDG_RUNTIME_DIR=" + quote(home);
    for (const auto &[key, value] : env)
        command += " " + key + "=" + quote(value);
    command += " xvfb-run -a -s '-screen 0 640x480x24' " + quote(VOXELFAIR_MESHLABSERVER);
    for (const std::string &a : args)
        command += " " + quote(a);
    const std::string log = home + "/output.txt";
    command += " > " + quote(log) + " 2>&1";

    MeshlabRun run;
    const int status = std::system(command.c_str());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    run.output = text.str();
    std::system(("rm -rf " + quote(home)).c_str());
    return run;
}
