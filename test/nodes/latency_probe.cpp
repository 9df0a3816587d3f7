// Benchmark probe (bench/realtime_loop.sh): measures the state rate and the
// controller's latency from a state's arrival to the cmd_vel it causes, both
// seen from this one process (same clock, same transport on both topics).
#include <aurora_msgs/DroneState.h>
#include <ros/callback_queue.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <algorithm>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  ros::init(argc, argv, "latency_probe");
  ros::NodeHandle nh, pnh("~");
  const double duration = pnh.param("duration", 30.0);
  std::vector<double> latencies_ms;
  std::vector<double> state_wall;
  ros::WallTime last_state;
  bool pending = false;
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  ros::Subscriber s1 = nh.subscribe<aurora_msgs::DroneState>(
      "state", 100,
      [&](const aurora_msgs::DroneState::ConstPtr&) {
        last_state = ros::WallTime::now();
        state_wall.push_back(last_state.toSec());
        pending = true;
      },
      ros::VoidConstPtr(), hints);
  ros::Subscriber s2 = nh.subscribe<geometry_msgs::Twist>(
      "cmd_vel", 100,
      [&](const geometry_msgs::Twist::ConstPtr&) {
        if (!pending) return;
        latencies_ms.push_back((ros::WallTime::now() - last_state).toSec() * 1e3);
        pending = false;
      },
      ros::VoidConstPtr(), hints);
  // Skip the first second (connections settling), then measure.
  const ros::WallTime warmup_end = ros::WallTime::now() + ros::WallDuration(1.0);
  while (ros::ok() && ros::WallTime::now() < warmup_end) ros::spinOnce(), ros::WallDuration(0.0005).sleep();
  latencies_ms.clear();
  state_wall.clear();
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(duration);
  ros::CallbackQueue* queue = ros::getGlobalCallbackQueue();
  while (ros::ok() && ros::WallTime::now() < end) queue->callAvailable(ros::WallDuration(0.001));
  if (state_wall.size() < 2 || latencies_ms.empty()) {
    std::fprintf(stderr, "latency_probe: no state/cmd_vel traffic\n");
    return 1;
  }
  std::sort(latencies_ms.begin(), latencies_ms.end());
  auto pct = [&](double p) {
    return latencies_ms[std::min(latencies_ms.size() - 1, size_t(p * (latencies_ms.size() - 1) + 0.5))];
  };
  const double span = state_wall.back() - state_wall.front();
  std::printf("{\"duration_s\": %.3f, \"states\": %zu, \"state_rate_hz\": %.4f, \"latency_samples\": %zu, "
              "\"latency_p50_ms\": %.4f, \"latency_p99_ms\": %.4f, \"latency_max_ms\": %.4f}\n",
              span, state_wall.size(), (state_wall.size() - 1) / span, latencies_ms.size(), pct(0.5),
              pct(0.99), latencies_ms.back());
  return 0;
}
