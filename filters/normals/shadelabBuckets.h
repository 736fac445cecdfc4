/**
 * @brief   indices grouped by key (a counting sort)
 *
 * The indices of `count` `keys` grouped by key, in order: those of key k are
 * Items[First[k]] to Items[First[k + 1] - 1]. The normals use it for the
 * face corners at each point and for the copies of each point.
 */
#ifndef shadelabBuckets_h
#define shadelabBuckets_h

#include "shadelabNormalsMesh.h"

#include <numeric>
#include <vector>

namespace shadelab::normals
{
struct Buckets
{
  std::vector<Id> First;
  std::vector<Id> Items;

  Buckets(const Id* keys, vtkIdType count, vtkIdType keyCount)
    : First(keyCount + 1, 0)
    , Items(count)
  {
    for (vtkIdType i = 0; i < count; ++i)
    {
      ++this->First[keys[i] + 1];
    }
    std::partial_sum(this->First.begin(), this->First.end(), this->First.begin());
    std::vector<Id> fill(this->First.begin(), this->First.end() - 1);
    for (vtkIdType i = 0; i < count; ++i)
    {
      this->Items[fill[keys[i]]++] = static_cast<Id>(i);
    }
  }
};
}

#endif
