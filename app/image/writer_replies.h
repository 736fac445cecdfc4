// The image writer's answers, in the order of its requests, while pictures
// are encoded in parallel (image_writer_main.cxx). A picture of one frame
// is encoded on a thread of its own, so that a batch's pictures are encoded
// while the next renders and beside each other; an animation's frames (one
// encoder, in order) and textures' decodes are done as they come. Each
// request's answer waits for those of the requests before it, and a
// picture waits for any earlier one still being written to the same file
// (however its name is spelt), so that the last one sent is the one left
// there. How many are in flight
// is for shadelab to bound: it waits for answers (image_writer_process.h).
#ifndef shadelab_writer_replies_h
#define shadelab_writer_replies_h

#include "shadelabTexture.h"

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace shadelab
{
/** A request's answer: one line, empty or the problem; after a decode's empty one, its image. */
struct WriterReply
{
  std::string Line;
  std::unique_ptr<TextureImage> Image;
};

class WriterReplies
{
public:
  /** Answers on fd, in order, from a thread of its own. */
  explicit WriterReplies(int fd);
  /** Waits for every request's work and answer (Finish). */
  ~WriterReplies();

  /** A picture of one frame for path: encoded (work) on a thread of its own. */
  void Encode(const std::string& path, std::function<std::string()> work);

  /**
   * A request done (work) as it comes, on the caller's thread, once any
   * picture still being written to path is.
   */
  void Answer(const std::string& path, const std::function<WriterReply()>& work);

  /** Waits until every answer is sent; false if one could not be (shadelab is gone). */
  bool Finish();

private:
  WriterReplies(const WriterReplies&) = delete;
  void operator=(const WriterReplies&) = delete;

  struct Pending
  {
    std::string File; // its output file's name, resolved (an image to decode's, for a decode)
    std::shared_future<WriterReply> Reply;
  };
  void WaitForFile(const std::string& file);
  void Push(const std::string& file, std::shared_future<WriterReply> reply);
  void SendInOrder();

  int Fd;
  std::mutex Mutex;
  std::condition_variable Changed;
  std::deque<Pending> Queue; // not yet answered, oldest first
  bool Closing = false;
  bool Broken = false; // an answer could not be sent
  std::thread Sender;
};
}

#endif
