#include "segmentation/detail/mergeConvex.h"

#include <algorithm>
#include <queue>
#include <set>
#include <tuple>
#include <vector>

#include "segmentation/detail/shape.h"

namespace solidtex::segmentation::detail {
namespace {

struct Piece {
  cv::Rect box;
  std::vector<cv::Point> hull;
  double filled = 0;  // pixels inside the outer outline, holes included
  double solidity = 0;
  int version = 0;  // bumped on every merge, to recognise stale queue entries
  std::set<int> neighbours;
};

// Counts the pixels of labels `a` or `b` inside `box` plus the holes they enclose: the pixels of
// the box that cannot reach the box's edge without crossing them. Reuses `buffer`; no contours.
class FilledCounter {
public:
  double count(const cv::Mat& labels, const cv::Rect& box, int a, int b) {
    const int w = box.width + 2, h = box.height + 2;  // a free frame around the box
    state_.assign(std::size_t(w) * std::size_t(h), kFree);
    for (int y = 0; y < box.height; ++y) {
      const int* l = labels.ptr<int>(box.y + y) + box.x;
      for (int x = 0; x < box.width; ++x)
        if (l[x] == a || l[x] == b) state_[std::size_t(y + 1) * w + std::size_t(x + 1)] = kInside;
    }
    std::size_t outside = floodOutside(w, h);
    return double(state_.size() - outside);
  }

private:
  enum : unsigned char { kFree, kInside, kOutside };

  // 4-connected, the dual of the 8-connected pieces.
  std::size_t floodOutside(int w, int h) {
    stack_.assign(1, 0);
    state_[0] = kOutside;
    std::size_t reached = 1;
    while (!stack_.empty()) {
      const int i = stack_.back();
      stack_.pop_back();
      const int x = i % w, y = i / w;
      const int next[4] = {x > 0 ? i - 1 : -1, x + 1 < w ? i + 1 : -1, y > 0 ? i - w : -1,
                           y + 1 < h ? i + w : -1};
      for (int n : next)
        if (n >= 0 && state_[std::size_t(n)] == kFree) {
          state_[std::size_t(n)] = kOutside;
          stack_.push_back(n);
          ++reached;
        }
    }
    return reached;
  }

  std::vector<unsigned char> state_;
  std::vector<int> stack_;
};

// The hull of a region is the hull of its leftmost and rightmost pixel on each row.
std::vector<cv::Point> hullOfLabel(const cv::Mat& labels, const cv::Rect& box, int label) {
  std::vector<cv::Point> extremes;
  for (int y = box.y; y < box.br().y; ++y) {
    const int* l = labels.ptr<int>(y);
    int first = -1, last = -1;
    for (int x = box.x; x < box.br().x; ++x)
      if (l[x] == label) last = x, first = first < 0 ? x : first;
    if (first >= 0) extremes.emplace_back(first, y), extremes.emplace_back(last, y);
  }
  return hullOf(extremes);
}

double solidityOf(double filled, const std::vector<cv::Point>& hull) {
  return std::min(1.0, filled / hullPixelArea(hull));
}

std::vector<cv::Rect> boxesAndNeighbours(const cv::Mat& labels, std::vector<Piece>& pieces) {
  std::vector<cv::Rect> boxes(pieces.size());
  for (int y = 0; y < labels.rows; ++y) {
    const int* l = labels.ptr<int>(y);
    const int* below = y + 1 < labels.rows ? labels.ptr<int>(y + 1) : nullptr;
    for (int x = 0; x < labels.cols; ++x) {
      if (l[x] <= 0) continue;
      cv::Rect& b = boxes[std::size_t(l[x])];
      b = b.empty() ? cv::Rect(x, y, 1, 1) : (b | cv::Rect(x, y, 1, 1));
      const auto touch = [&](int other) {
        if (other > 0 && other != l[x])
          pieces[std::size_t(l[x])].neighbours.insert(other),
              pieces[std::size_t(other)].neighbours.insert(l[x]);
      };
      if (x + 1 < labels.cols) touch(l[x + 1]);
      if (below) {
        touch(below[x]);
        if (x > 0) touch(below[x - 1]);
        if (x + 1 < labels.cols) touch(below[x + 1]);
      }
    }
  }
  return boxes;
}

struct Candidate {
  double gain;
  int a, b, versionA, versionB;
  bool operator<(const Candidate& o) const {  // priority_queue pops the largest gain, then smallest ids
    return std::tie(gain, o.a, o.b) < std::tie(o.gain, a, b);
  }
};

class Merger {
public:
  explicit Merger(cv::Mat& labels) : labels_(labels) {
    double maxLabel = 0;
    cv::minMaxLoc(labels, nullptr, &maxLabel);
    pieces_.resize(std::size_t(maxLabel) + 1);
    const std::vector<cv::Rect> boxes = boxesAndNeighbours(labels, pieces_);
    for (int i = 1; i < int(pieces_.size()); ++i) {
      Piece& p = pieces_[std::size_t(i)];
      if ((p.box = boxes[std::size_t(i)]).empty()) continue;
      p.filled = counter_.count(labels_, p.box, i, i);
      p.hull = hullOfLabel(labels_, p.box, i);
      p.solidity = solidityOf(p.filled, p.hull);
    }
    for (int a = 1; a < int(pieces_.size()); ++a)
      for (int b : pieces_[std::size_t(a)].neighbours)
        if (a < b) consider(a, b);
  }

  void run() {
    while (!queue_.empty()) {
      const Candidate c = queue_.top();
      queue_.pop();
      if (c.versionA == pieces_[std::size_t(c.a)].version && c.versionB == pieces_[std::size_t(c.b)].version)
        merge(c.a, c.b);
    }
  }

private:
  struct Union {
    double filled, solidity;
    std::vector<cv::Point> hull;
  };

  Union unite(int a, int b) {
    const Piece& pa = pieces_[std::size_t(a)];
    const Piece& pb = pieces_[std::size_t(b)];
    std::vector<cv::Point> points = pa.hull;
    points.insert(points.end(), pb.hull.begin(), pb.hull.end());
    Union u{counter_.count(labels_, pa.box | pb.box, a, b), 0, hullOf(points)};
    u.solidity = solidityOf(u.filled, u.hull);
    return u;
  }

  // Queues the pair when the union, holes filled, is at least as solid as the pieces on average.
  void consider(int a, int b) {
    const Piece& pa = pieces_[std::size_t(a)];
    const Piece& pb = pieces_[std::size_t(b)];
    const double mean = (pa.filled * pa.solidity + pb.filled * pb.solidity) / (pa.filled + pb.filled);
    const double gain = unite(a, b).solidity - mean;
    if (gain >= 0) queue_.push({gain, a, b, pa.version, pb.version});
  }

  void merge(int a, int b) {
    Union u = unite(a, b);
    Piece& pa = pieces_[std::size_t(a)];
    Piece& pb = pieces_[std::size_t(b)];
    labels_(pb.box).setTo(a, labels_(pb.box) == b);
    pa.box |= pb.box;
    pa.filled = u.filled;
    pa.solidity = u.solidity;
    pa.hull = std::move(u.hull);
    ++pa.version;
    for (int n : pb.neighbours) {
      pieces_[std::size_t(n)].neighbours.erase(b);
      if (n != a) pieces_[std::size_t(n)].neighbours.insert(a), pa.neighbours.insert(n);
    }
    pb = Piece{};
    pb.version = -1;
    for (int n : pa.neighbours) consider(std::min(a, n), std::max(a, n));
  }

  cv::Mat& labels_;
  std::vector<Piece> pieces_;
  std::priority_queue<Candidate> queue_;
  FilledCounter counter_;
};

void relabelInRasterOrder(cv::Mat& labels) {
  double maxLabel = 0;
  cv::minMaxLoc(labels, nullptr, &maxLabel);
  std::vector<int> renumber(std::size_t(maxLabel) + 1, 0);
  int next = 0;
  for (int y = 0; y < labels.rows; ++y) {
    int* l = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (l[x] <= 0) continue;
      int& id = renumber[std::size_t(l[x])];
      if (id == 0) id = ++next;
      l[x] = id;
    }
  }
}

}  // namespace

void mergeWhereMoreConvex(cv::Mat& labels) {
  CV_Assert(labels.type() == CV_32SC1);
  Merger(labels).run();
  relabelInRasterOrder(labels);
}

}  // namespace solidtex::segmentation::detail
