#include "image/writer_replies.h"

#include "image/image_writer_protocol.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace shadelab
{
namespace
{
// One file, however its name is spelt ("out.png", "./out.png", through a
// link): resolved as far as it exists.
std::string SameFile(const std::string& path)
{
  std::error_code error;
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path, error).lexically_normal().string()
               : resolved.string();
}
}

WriterReplies::WriterReplies(int fd)
  : Fd(fd)
  , Sender([this] { this->SendInOrder(); })
{
}

WriterReplies::~WriterReplies()
{
  (void)this->Finish();
}

void WriterReplies::WaitForFile(const std::string& file)
{
  std::vector<std::shared_future<WriterReply>> same;
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    for (const Pending& pending : this->Queue)
    {
      if (pending.File == file)
      {
        same.push_back(pending.Reply);
      }
    }
  }
  for (const auto& reply : same)
  {
    reply.wait();
  }
}

void WriterReplies::Push(const std::string& file, std::shared_future<WriterReply> reply)
{
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    this->Queue.push_back({ file, std::move(reply) });
  }
  this->Changed.notify_all();
}

void WriterReplies::Encode(const std::string& path, std::function<std::string()> work)
{
  const std::string file = SameFile(path);
  this->WaitForFile(file);
  this->Push(file,
    std::async(std::launch::async,
      [work = std::move(work)] {
        return WriterReply{ work(), {} };
      })
      .share());
}

void WriterReplies::Answer(const std::string& path, const std::function<WriterReply()>& work)
{
  const std::string file = SameFile(path);
  this->WaitForFile(file);
  std::promise<WriterReply> done;
  done.set_value(work());
  this->Push(file, done.get_future().share());
}

bool WriterReplies::Finish()
{
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    this->Closing = true;
  }
  this->Changed.notify_all();
  if (this->Sender.joinable())
  {
    this->Sender.join();
  }
  return !this->Broken;
}

void WriterReplies::SendInOrder()
{
  for (;;)
  {
    std::shared_future<WriterReply> next;
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->Changed.wait(lock, [this] { return !this->Queue.empty() || this->Closing; });
      if (this->Queue.empty())
      {
        return;
      }
      next = this->Queue.front().Reply;
    }
    // Waited for outside the lock: later requests keep coming meanwhile.
    const WriterReply& reply = next.get();
    std::string line = reply.Line;
    std::replace(line.begin(), line.end(), '\n', ' ');
    line += '\n';
    // Once shadelab is gone, the rest is still finished (whole files) but not answered.
    if (!this->Broken &&
      (write(this->Fd, line.data(), line.size()) != static_cast<ssize_t>(line.size()) ||
        (reply.Image && !SendTextureImage(this->Fd, *reply.Image))))
    {
      this->Broken = true;
    }
    const std::lock_guard<std::mutex> lock(this->Mutex);
    this->Queue.pop_front();
  }
}
}
