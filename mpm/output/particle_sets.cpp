#include "mpm/output/particle_sets.hpp"

#include <algorithm>
#include <map>

namespace impact::mpm {

std::size_t ParticleSets::add(const std::vector<std::uint64_t>& local, const Communicator& comm) {
  return add(comm.concatenate(local));
}

std::size_t ParticleSets::add(std::vector<std::uint64_t> ids) {
  std::sort(ids.begin(), ids.end());
  sets_.push_back(std::move(ids));
  // The union with its owners, rebuilt (sets are added once, at the start).
  std::map<std::uint64_t, std::vector<std::size_t>> owners;
  for (std::size_t s = 0; s < sets_.size(); ++s)
    for (const std::uint64_t id : sets_[s]) owners[id].push_back(s);
  union_.clear();
  owners_.clear();
  first_owner_.assign(1, 0);
  for (const auto& [id, sets] : owners) {
    union_.push_back(id);
    owners_.insert(owners_.end(), sets.begin(), sets.end());
    first_owner_.push_back(owners_.size());
  }
  return sets_.size() - 1;
}

std::vector<std::vector<ParticleSets::Member>> ParticleSets::find(const Particles& P) const {
  std::vector<std::vector<Member>> found(sets_.size());
  if (P.id.empty()) {  // one rank in seed order: the seed index is the array index
    for (std::size_t s = 0; s < sets_.size(); ++s) {
      found[s].reserve(sets_[s].size());
      for (std::size_t i = 0; i < sets_[s].size(); ++i)
        found[s].push_back({static_cast<std::size_t>(sets_[s][i]), i});
    }
    return found;
  }
  for (std::size_t p = 0; p < P.size(); ++p) {
    const auto k = std::lower_bound(union_.begin(), union_.end(), P.id[p]);
    if (k == union_.end() || *k != P.id[p]) continue;
    const std::size_t u = static_cast<std::size_t>(k - union_.begin());
    for (std::size_t o = first_owner_[u]; o < first_owner_[u + 1]; ++o) {
      const std::vector<std::uint64_t>& set = sets_[owners_[o]];
      const auto i = std::lower_bound(set.begin(), set.end(), P.id[p]) - set.begin();
      found[owners_[o]].push_back({p, static_cast<std::size_t>(i)});
    }
  }
  return found;
}

}  // namespace impact::mpm
