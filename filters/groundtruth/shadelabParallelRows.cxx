#include "shadelabParallelRows.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace shadelab
{
void ForEachRow(int first, int last, const std::function<void(int)>& row)
{
  std::atomic<int> next{ first };
  const auto rows = [&]
  {
    for (int y; (y = next++) < last;)
    {
      row(y);
    }
  };
  std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()) - 1);
  for (std::thread& thread : threads)
  {
    thread = std::thread(rows);
  }
  rows();
  for (std::thread& thread : threads)
  {
    thread.join();
  }
}
}
