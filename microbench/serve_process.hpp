#pragma once
// A `foldkit serve --port 0` child process for bench_serve and the ServeApi tests: started on a
// root folder, its port read from the first line it prints, stopped (SIGTERM, then SIGKILL) when
// the object goes.
#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace foldkit::bench {

class ServeProcess {
 public:
  // `cli` serves `root`; its stdout and stderr go to `log`; `extra` are more options of serve.
  ServeProcess(const std::string& cli, const std::string& root, const std::string& log, const std::vector<std::string>& extra = {})
      : log_(log) {
    std::vector<std::string> args = {cli, "serve", "--port", "0", "--root", root};
    args.insert(args.end(), extra.begin(), extra.end());
    pid_ = fork();
    if (pid_ == 0) {
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, 1);
      dup2(fd, 2);
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    // The port it chose is on its first line (at most 10 s).
    for (int i = 0; i < 200 && port_ == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      const std::string text = this->log();
      const auto at = text.find("http://127.0.0.1:");
      if (at != std::string::npos && text.find('/', at + 17) != std::string::npos) port_ = std::stoi(text.substr(at + 17));
    }
  }
  ~ServeProcess() {
    kill(pid_, SIGTERM);
    for (int i = 0; i < 100; ++i) {
      if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  // 0 when the server did not start (log() says why).
  int port() const { return port_; }
  std::string log() const {
    std::ifstream in(log_);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  std::string log_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace foldkit::bench
