// rviz_visual_tools::RvizVisualTools, written anew with upstream's marker kinds, namespaces,
// colours, sizes and id rules (rviz_visual_tools noetic-devel 3.9.1 src/rviz_visual_tools.cpp;
// "l." below are its lines).
#include <rviz_visual_tools/rviz_visual_tools.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rviz_visual_tools
{
namespace
{
const std::string LOGNAME = "visual_tools";

// Queue of the marker publisher (l. 283)
const std::size_t MARKER_QUEUE_SIZE = 10;
// How often waitForSubscriber looks for a subscriber, Hz (l. 314)
const double SUBSCRIBER_POLL_RATE = 200.0;
// An arrow of length 0 is this many times its scale long (l. 1345-1348)
const double ARROW_AUTO_LENGTH_FACTOR = 10.0;
// An arrow between two points: head diameter and head length over the shaft's (l. 1420-1421)
const double ARROW_HEAD_DIAMETER_FACTOR = 2.0;
const double ARROW_HEAD_LENGTH_FACTOR = 3.0;
// An axis is this many times as long as its cylinders' radius (l. 1449-1450)
const double AXIS_LENGTH_PER_RADIUS = 10.0;
// publishAxisLabeled puts its text this far off the axis' origin on x, y and z (l. 1440-1442)
const double AXIS_LABEL_OFFSET = 0.05;
// A wireframe rectangle's lines are a quarter of the scale (l. 2293)
const double WIREFRAME_RECTANGLE_SCALE = 0.25;
// A cone is drawn as this many triangles of this angle around its axis (l. 941, 945)
const std::size_t CONE_TRIANGLES = 32;
const double CONE_TRIANGLE_ANGLE = M_PI / 16.0;
// publishABCDPlane draws a cuboid this thick (l. 991)
const double PLANE_THICKNESS = 0.001;
// createRandColor: tries, and the least r + g + b accepted (l. 588, 605)
const std::size_t RAND_COLOR_ATTEMPTS = 20;
const double RAND_COLOR_MIN_SUM = 1.5;

// Upstream's size of each scale in metres (l. 665-707)
double scaleSize(scales scale)
{
  switch (scale)
  {
    case XXXXSMALL:
      return 0.001;
    case XXXSMALL:
      return 0.0025;
    case XXSMALL:
      return 0.005;
    case XSMALL:
      return 0.0065;
    case SMALL:
      return 0.0075;
    case MEDIUM:
      return 0.01;
    case LARGE:
      return 0.025;
    case XLARGE:
      return 0.05;
    case XXLARGE:
      return 0.075;
    case XXXLARGE:
      return 0.1;
    case XXXXLARGE:
      return 0.5;
  }
  ROS_ERROR_STREAM_NAMED(LOGNAME, "Not implemented yet");
  return 0.0;
}

std_msgs::ColorRGBA rgba(double r, double g, double b, double a)
{
  std_msgs::ColorRGBA color;
  color.r = r;
  color.g = g;
  color.b = b;
  color.a = a;
  return color;
}

geometry_msgs::Vector3 uniformScale(double size)
{
  geometry_msgs::Vector3 scale;
  scale.x = size;
  scale.y = size;
  scale.z = size;
  return scale;
}

// The next id of a marker kind, or the caller's id (0 asks for the next one)
void takeId(visualization_msgs::Marker& marker, std::size_t id)
{
  marker.id = (id == 0) ? marker.id + 1 : static_cast<int>(id);
}

void prepareMarker(visualization_msgs::Marker& marker, const std::string& frame, const std::string& ns, int32_t type,
                   const ros::Duration& lifetime)
{
  marker.header.frame_id = frame;
  marker.header.stamp = ros::Time();
  marker.ns = ns;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.lifetime = lifetime;
  marker.pose = RvizVisualTools::getIdentityPose();
}
}  // namespace

const std::string RvizVisualTools::NAME = "visual_tools";

// The colours getRandColor picks from (l. 60-62)
const std::array<colors, 14> RvizVisualTools::ALL_RAND_COLORS = { RED,   GREEN,  BLUE,  GREY,       DARK_GREY,
                                                                  WHITE, ORANGE, YELLOW, BROWN,     PINK,
                                                                  LIME_GREEN, PURPLE, CYAN, MAGENTA };

RvizVisualTools::RvizVisualTools(std::string base_frame, std::string marker_topic, ros::NodeHandle nh)
  : nh_(nh), marker_topic_(std::move(marker_topic)), base_frame_(std::move(base_frame))
{
  marker_lifetime_ = ros::Duration(0.0);  // for ever
  loadRvizMarkers();
}

bool RvizVisualTools::deleteAllMarkers()
{
  return publishMarker(reset_marker_);
}

void RvizVisualTools::resetMarkerCounts()
{
  for (visualization_msgs::Marker* marker :
       { &arrow_marker_, &sphere_marker_, &block_marker_, &cylinder_marker_, &mesh_marker_, &text_marker_,
         &cuboid_marker_, &line_strip_marker_, &line_list_marker_, &spheres_marker_, &triangle_marker_ })
  {
    marker->id++;
  }
}

bool RvizVisualTools::loadRvizMarkers()
{
  // Kinds and namespaces of l. 99-273. DELETEALL (3) clears every namespace of the display.
  reset_marker_.header.frame_id = base_frame_;
  reset_marker_.header.stamp = ros::Time();
  reset_marker_.ns = "deleteAllMarkers";
  reset_marker_.action = visualization_msgs::Marker::DELETEALL;
  reset_marker_.pose.orientation.w = 1;

  using visualization_msgs::Marker;
  prepareMarker(arrow_marker_, base_frame_, "Arrow", Marker::ARROW, marker_lifetime_);
  prepareMarker(cuboid_marker_, base_frame_, "Cuboid", Marker::CUBE, marker_lifetime_);
  prepareMarker(line_strip_marker_, base_frame_, "Line", Marker::LINE_STRIP, marker_lifetime_);
  prepareMarker(line_list_marker_, base_frame_, "Line_List", Marker::LINE_LIST, marker_lifetime_);
  prepareMarker(spheres_marker_, base_frame_, "Spheres", Marker::SPHERE_LIST, marker_lifetime_);
  prepareMarker(block_marker_, base_frame_, "Block", Marker::CUBE, marker_lifetime_);
  prepareMarker(cylinder_marker_, base_frame_, "", Marker::CYLINDER, marker_lifetime_);
  prepareMarker(mesh_marker_, base_frame_, "", Marker::MESH_RESOURCE, marker_lifetime_);
  prepareMarker(sphere_marker_, base_frame_, "Sphere", Marker::SPHERE, marker_lifetime_);
  prepareMarker(text_marker_, base_frame_, "Text", Marker::TEXT_VIEW_FACING, marker_lifetime_);
  prepareMarker(triangle_marker_, base_frame_, "Triangle", Marker::TRIANGLE_LIST, marker_lifetime_);
  return true;
}

void RvizVisualTools::loadMarkerPub(bool wait_for_subscriber, bool latched)
{
  if (pub_rviz_markers_)
  {
    return;
  }
  pub_rviz_markers_ = nh_.advertise<visualization_msgs::MarkerArray>(marker_topic_, MARKER_QUEUE_SIZE, latched);
  ROS_DEBUG_STREAM_NAMED(LOGNAME, "Publishing Rviz markers on topic " << pub_rviz_markers_.getTopic());
  if (wait_for_subscriber)
  {
    waitForSubscriber(pub_rviz_markers_);
  }
}

void RvizVisualTools::waitForMarkerPub()
{
  waitForSubscriber(pub_rviz_markers_, 0, true);
}

void RvizVisualTools::waitForMarkerPub(double wait_time)
{
  waitForSubscriber(pub_rviz_markers_, wait_time, false);
}

bool RvizVisualTools::waitForSubscriber(const ros::Publisher& pub, double wait_time, bool blocking)
{
  // l. 304-353
  if (pub.getTopic().empty())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "loadMarkerPub() has not been called yet, unable to wait for subscriber.");
  }
  const ros::Time deadline = ros::Time::now() + ros::Duration(wait_time);
  if (blocking && pub.getNumSubscribers() == 0)
  {
    ROS_INFO_STREAM_NAMED(LOGNAME, "Topic '" << pub.getTopic() << "' waiting for subscriber...");
  }
  ros::Rate poll_rate(SUBSCRIBER_POLL_RATE);
  while (pub.getNumSubscribers() == 0)
  {
    if (!blocking && ros::Time::now() > deadline)
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, "Topic '" << pub.getTopic() << "' unable to connect to any subscribers within "
                                               << wait_time
                                               << " sec. It is possible initially published visual messages "
                                                  "will be lost.");
      return false;
    }
    ros::spinOnce();
    poll_rate.sleep();
    if (!ros::ok())
    {
      return false;
    }
  }
  pub_rviz_markers_connected_ = true;
  return true;
}

void RvizVisualTools::setLifetime(double lifetime)
{
  marker_lifetime_ = ros::Duration(lifetime);
  for (visualization_msgs::Marker* marker : { &arrow_marker_, &cuboid_marker_, &line_strip_marker_, &sphere_marker_,
                                              &block_marker_, &mesh_marker_, &cylinder_marker_, &text_marker_ })
  {
    marker->lifetime = marker_lifetime_;
  }
}

colors RvizVisualTools::getRandColor()
{
  return ALL_RAND_COLORS[iRand(0, ALL_RAND_COLORS.size() - 1)];
}

std_msgs::ColorRGBA RvizVisualTools::getColor(colors color) const
{
  // Upstream's values (l. 376-507); the translucent ones and CLEAR keep their own alpha
  switch (color)
  {
    case RED:
      return rgba(0.8, 0.1, 0.1, alpha_);
    case GREEN:
      return rgba(0.1, 0.8, 0.1, alpha_);
    case GREY:
      return rgba(0.9, 0.9, 0.9, alpha_);
    case DARK_GREY:
      return rgba(0.6, 0.6, 0.6, alpha_);
    case WHITE:
      return rgba(1.0, 1.0, 1.0, alpha_);
    case ORANGE:
      return rgba(1.0, 0.5, 0.0, alpha_);
    case TRANSLUCENT_LIGHT:
      return rgba(0.1, 0.1, 0.1, 0.1);
    case TRANSLUCENT:
      return rgba(0.1, 0.1, 0.1, 0.25);
    case TRANSLUCENT_DARK:
      return rgba(0.1, 0.1, 0.1, 0.5);
    case BLACK:
      return rgba(0.0, 0.0, 0.0, alpha_);
    case YELLOW:
      return rgba(1.0, 1.0, 0.0, alpha_);
    case BROWN:
      return rgba(0.597, 0.296, 0.0, alpha_);
    case PINK:
      return rgba(1.0, 0.4, 1.0, alpha_);
    case LIME_GREEN:
      return rgba(0.6, 1.0, 0.2, alpha_);
    case CLEAR:
      return rgba(1.0, 1.0, 1.0, 0.0);
    case PURPLE:
      return rgba(0.597, 0.0, 0.597, alpha_);
    case CYAN:
      return rgba(0.0, 1.0, 1.0, alpha_);
    case MAGENTA:
      return rgba(1.0, 0.0, 1.0, alpha_);
    case RAND:
      return createRandColor();
    case DEFAULT:
      ROS_WARN_STREAM_NAMED(LOGNAME, "The 'DEFAULT' color should probably not be used with getColor(). Defaulting to "
                                     "blue.");
      return rgba(0.1, 0.1, 0.8, alpha_);
    case BLUE:
    default:
      return rgba(0.1, 0.1, 0.8, alpha_);
  }
}

colors RvizVisualTools::intToRvizColor(std::size_t color)
{
  // The enum's own values (l. 509-538); anything else is DEFAULT
  return color <= static_cast<std::size_t>(DEFAULT) ? static_cast<colors>(color) : DEFAULT;
}

scales RvizVisualTools::intToRvizScale(std::size_t scale)
{
  if (scale < static_cast<std::size_t>(XXXXSMALL) || scale > static_cast<std::size_t>(XXXXLARGE))
  {
    throw std::runtime_error("Unknown size");
  }
  return static_cast<scales>(scale);
}

std::string RvizVisualTools::scaleToString(scales scale)
{
  static const char* const NAMES[] = { "XXXXSMALL", "XXXSMALL", "XXSMALL",  "XSMALL",   "SMALL",    "MEDIUM",
                                       "LARGE",     "XLARGE",   "XXLARGE", "XXXLARGE", "XXXXLARGE" };
  if (scale < XXXXSMALL || scale > XXXXLARGE)
  {
    throw std::runtime_error("Unknown size");
  }
  return NAMES[scale - XXXXSMALL];
}

std_msgs::ColorRGBA RvizVisualTools::createRandColor() const
{
  // Not too dark: r + g + b of at least 1.5, within a bounded number of tries (l. 584-611)
  std_msgs::ColorRGBA result;
  std::size_t attempts = 0;
  do
  {
    result.r = fRand(0.0, 1.0);
    result.g = fRand(0.0, 1.0);
    result.b = fRand(0.0, 1.0);
    if (++attempts > RAND_COLOR_ATTEMPTS)
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, "Unable to find appropriate random color after " << RAND_COLOR_ATTEMPTS
                                                                                      << " attempts");
      break;
    }
  } while (result.r + result.g + result.b < RAND_COLOR_MIN_SUM);
  result.a = alpha_;
  return result;
}

double RvizVisualTools::slerp(double start, double end, double range, double value)
{
  return start + (((end - start) / range) * value);
}

std_msgs::ColorRGBA RvizVisualTools::getColorScale(double value) const
{
  // 0 red, 0.5 yellow, 1 green, linear between (l. 618-663)
  const double half = 0.5;
  if (value < 0)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Intensity value for color scale is below range [0,1], value: " << value);
    value = 0;
  }
  else if (value > 1)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Intensity value for color scale is above range [0,1], value: " << value);
    value = 1;
  }
  if (value == 0.0)
  {
    return getColor(RED);
  }
  if (value == 1.0)
  {
    return getColor(GREEN);
  }
  std_msgs::ColorRGBA start = getColor(value <= half ? RED : YELLOW);
  std_msgs::ColorRGBA end = getColor(value <= half ? YELLOW : GREEN);
  if (value > half)
  {
    value = std::fmod(value, half);
  }
  return rgba(slerp(start.r, end.r, half, value), slerp(start.g, end.g, half, value),
              slerp(start.b, end.b, half, value), alpha_);
}

geometry_msgs::Vector3 RvizVisualTools::getScale(scales scale, double marker_scale) const
{
  return uniformScale(scaleSize(scale) * marker_scale * global_scale_);
}

Eigen::Vector3d RvizVisualTools::getCenterPoint(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
{
  return (a + b) / 2.0;
}

Eigen::Isometry3d RvizVisualTools::getVectorBetweenPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
{
  // A pose at a whose x axis points to b: the shortest rotation of z onto b - a, then x onto z
  // (l. 726-805, whose rotation this is). Along z (up or down) upstream keeps x on +z.
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::AngleAxisd x_onto_z(-0.5 * M_PI, Eigen::Vector3d::UnitY());
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  if (axis.cross(up).isZero(0.0))
  {
    result = x_onto_z;
  }
  else
  {
    result = Eigen::Quaterniond::FromTwoVectors(up, axis) * x_onto_z;
  }
  result.translation() = a;
  return result;
}

bool RvizVisualTools::publishMarker(visualization_msgs::Marker& marker)
{
  marker.frame_locked = frame_locking_enabled_;
  markers_.markers.push_back(marker);
  if (!batch_publishing_enabled_)
  {
    return trigger();
  }
  return true;
}

void RvizVisualTools::enableBatchPublishing(bool enable)
{
  batch_publishing_enabled_ = enable;
}

void RvizVisualTools::enableFrameLocking(bool enable)
{
  frame_locking_enabled_ = enable;
}

bool RvizVisualTools::triggerEvery(std::size_t queueSize)
{
  if (markers_.markers.size() >= queueSize || queueSize == 0)
  {
    return trigger();
  }
  return false;
}

bool RvizVisualTools::trigger()
{
  if (!batch_publishing_enabled_)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Batch publishing triggered but it was not enabled (unnecessary function call)");
  }
  if (markers_.markers.empty())
  {
    return false;
  }
  const bool result = publishMarkers(markers_);
  markers_.markers.clear();
  return result;
}

bool RvizVisualTools::publishMarkers(visualization_msgs::MarkerArray& markers)
{
  if (!pub_rviz_markers_)
  {
    loadMarkerPub();
  }
  // The first send waits (0.5 s) for rviz to connect, once (l. 866-874)
  if (!pub_rviz_markers_waited_ && !pub_rviz_markers_connected_)
  {
    ROS_DEBUG_STREAM_NAMED(LOGNAME, "Waiting for subscribers before publishing markers...");
    waitForSubscriber(pub_rviz_markers_);
    pub_rviz_markers_waited_ = true;
  }
  if (markers.markers.empty())
  {
    return false;
  }
  for (visualization_msgs::Marker& marker : markers.markers)
  {
    if (psychedelic_mode_)
    {
      marker.color = rgba(1.0 - marker.color.r, 1.0 - marker.color.g, 1.0 - marker.color.b, marker.color.a);
      for (std_msgs::ColorRGBA& color : marker.colors)
      {
        color = rgba(1.0 - color.r, 1.0 - color.g, 1.0 - color.b, color.a);
      }
    }
    // rviz refuses a marker whose quaternion is not normalised: normalise, and a zero one is
    // the identity (l. 899-921)
    geometry_msgs::Quaternion& q = marker.pose.orientation;
    const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (norm < std::numeric_limits<double>::epsilon())
    {
      q.w = 1;
      q.x = q.y = q.z = 0;
    }
    else
    {
      q.w /= norm;
      q.x /= norm;
      q.y /= norm;
      q.z /= norm;
    }
  }
  pub_rviz_markers_.publish(markers);
  return true;
}

bool RvizVisualTools::publishTriangles(const geometry_msgs::Pose& pose, const std::vector<geometry_msgs::Point>& corners,
                                       colors color)
{
  triangle_marker_.header.stamp = ros::Time::now();
  triangle_marker_.id++;
  triangle_marker_.color = getColor(color);
  triangle_marker_.pose = pose;
  triangle_marker_.scale = uniformScale(1.0);
  triangle_marker_.points = corners;
  return publishMarker(triangle_marker_);
}

bool RvizVisualTools::publishCone(const Eigen::Isometry3d& pose, double angle, colors color, double scale)
{
  return publishCone(convertPose(pose), angle, color, scale);
}

bool RvizVisualTools::publishCone(const geometry_msgs::Pose& pose, double angle, colors color, double scale)
{
  // A fan of triangles from the apex along x, its rim at x = scale with radius scale / angle
  // (l. 932-971)
  std::vector<geometry_msgs::Point> corners;
  geometry_msgs::Point apex;
  double theta = 0;
  for (std::size_t i = 0; i < CONE_TRIANGLES; ++i, theta += CONE_TRIANGLE_ANGLE)
  {
    geometry_msgs::Point p1;
    p1.x = scale;
    p1.y = scale * std::cos(theta) / angle;
    p1.z = scale * std::sin(theta) / angle;
    geometry_msgs::Point p2;
    p2.x = scale;
    p2.y = scale * std::cos(theta + CONE_TRIANGLE_ANGLE) / angle;
    p2.z = scale * std::sin(theta + CONE_TRIANGLE_ANGLE) / angle;
    corners.push_back(apex);
    corners.push_back(p1);
    corners.push_back(p2);
  }
  return publishTriangles(pose, corners, color);
}

bool RvizVisualTools::publishABCDPlane(const double A, const double B, const double C, const double D, colors color,
                                       double x_width, double y_width)
{
  // The plane Ax + By + Cz + D = 0 as a thin cuboid centred on its point nearest the origin
  // (l. 973-995)
  const Eigen::Vector3d normal(A, B, C);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = -(D / normal.norm()) * normal.normalized();
  pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal).toRotationMatrix();
  publishCuboid(pose, x_width, y_width, PLANE_THICKNESS, color);
  return true;
}

namespace
{
// Two triangles over the square of corners c0..c3 (l. 1031-1038)
std::vector<geometry_msgs::Point> squareTriangles(const std::array<Eigen::Vector3d, 4>& c)
{
  std::vector<geometry_msgs::Point> corners;
  for (std::size_t index : { 0, 1, 2, 2, 3, 0 })
  {
    corners.push_back(RvizVisualTools::convertPoint(c[index]));
  }
  return corners;
}
}  // namespace

bool RvizVisualTools::publishXYPlane(const Eigen::Isometry3d& pose, colors color, double scale)
{
  return publishXYPlane(convertPose(pose), color, scale);
}

bool RvizVisualTools::publishXYPlane(const geometry_msgs::Pose& pose, colors color, double scale)
{
  return publishTriangles(pose,
                          squareTriangles({ Eigen::Vector3d(scale, scale, 0), Eigen::Vector3d(-scale, scale, 0),
                                            Eigen::Vector3d(-scale, -scale, 0), Eigen::Vector3d(scale, -scale, 0) }),
                          color);
}

bool RvizVisualTools::publishXZPlane(const Eigen::Isometry3d& pose, colors color, double scale)
{
  return publishXZPlane(convertPose(pose), color, scale);
}

bool RvizVisualTools::publishXZPlane(const geometry_msgs::Pose& pose, colors color, double scale)
{
  return publishTriangles(pose,
                          squareTriangles({ Eigen::Vector3d(scale, 0, scale), Eigen::Vector3d(-scale, 0, scale),
                                            Eigen::Vector3d(-scale, 0, -scale), Eigen::Vector3d(scale, 0, -scale) }),
                          color);
}

bool RvizVisualTools::publishYZPlane(const Eigen::Isometry3d& pose, colors color, double scale)
{
  return publishYZPlane(convertPose(pose), color, scale);
}

bool RvizVisualTools::publishYZPlane(const geometry_msgs::Pose& pose, colors color, double scale)
{
  return publishTriangles(pose,
                          squareTriangles({ Eigen::Vector3d(0, scale, scale), Eigen::Vector3d(0, -scale, scale),
                                            Eigen::Vector3d(0, -scale, -scale), Eigen::Vector3d(0, scale, -scale) }),
                          color);
}

bool RvizVisualTools::publishSphere(const Eigen::Isometry3d& pose, colors color, scales scale, const std::string& ns,
                                    std::size_t id)
{
  return publishSphere(convertPose(pose), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const Eigen::Vector3d& point, colors color, scales scale, const std::string& ns,
                                    std::size_t id)
{
  return publishSphere(convertPointToPose(convertPoint(point)), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const Eigen::Vector3d& point, colors color, double scale, const std::string& ns,
                                    std::size_t id)
{
  return publishSphere(convertPointToPose(convertPoint(point)), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::Point& point, colors color, scales scale,
                                    const std::string& ns, std::size_t id)
{
  return publishSphere(convertPointToPose(point), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::Pose& pose, colors color, scales scale, const std::string& ns,
                                    std::size_t id)
{
  return publishSphere(pose, color, getScale(scale), ns, id);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::Pose& pose, colors color, double scale, const std::string& ns,
                                    std::size_t id)
{
  return publishSphere(pose, color, uniformScale(scale * global_scale_), ns, id);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::Pose& pose, colors color, const geometry_msgs::Vector3 scale,
                                    const std::string& ns, std::size_t id)
{
  return publishSphere(pose, getColor(color), scale, ns, id);
}

bool RvizVisualTools::publishSphere(const Eigen::Isometry3d& pose, const std_msgs::ColorRGBA& color,
                                    const geometry_msgs::Vector3 scale, const std::string& ns, std::size_t id)
{
  return publishSphere(convertPose(pose), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const Eigen::Vector3d& point, const std_msgs::ColorRGBA& color,
                                    const geometry_msgs::Vector3 scale, const std::string& ns, std::size_t id)
{
  return publishSphere(convertPointToPose(convertPoint(point)), color, scale, ns, id);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::Pose& pose, const std_msgs::ColorRGBA& color,
                                    const geometry_msgs::Vector3 scale, const std::string& ns, std::size_t id)
{
  sphere_marker_.header.stamp = ros::Time::now();
  takeId(sphere_marker_, id);
  sphere_marker_.pose = pose;
  sphere_marker_.color = color;
  sphere_marker_.scale = scale;
  sphere_marker_.ns = ns;
  return publishMarker(sphere_marker_);
}

bool RvizVisualTools::publishSphere(const geometry_msgs::PoseStamped& pose, colors color,
                                    const geometry_msgs::Vector3 scale, const std::string& ns, std::size_t id)
{
  // In the pose's own frame, then back to the base frame (l. 1226-1251)
  sphere_marker_.header = pose.header;
  takeId(sphere_marker_, id);
  sphere_marker_.pose = pose.pose;
  sphere_marker_.color = getColor(color);
  sphere_marker_.scale = scale;
  sphere_marker_.ns = ns;
  publishMarker(sphere_marker_);
  sphere_marker_.header.frame_id = base_frame_;
  return true;
}

bool RvizVisualTools::publishSpheres(const EigenSTL::vector_Vector3d& points, colors color, scales scale,
                                     const std::string& ns)
{
  std::vector<geometry_msgs::Point> points_msg;
  for (const Eigen::Vector3d& point : points)
  {
    points_msg.push_back(convertPoint(point));
  }
  return publishSpheres(points_msg, color, scale, ns);
}

bool RvizVisualTools::publishSpheres(const EigenSTL::vector_Vector3d& points, colors color, double scale,
                                     const std::string& ns)
{
  std::vector<geometry_msgs::Point> points_msg;
  for (const Eigen::Vector3d& point : points)
  {
    points_msg.push_back(convertPoint(point));
  }
  return publishSpheres(points_msg, color, scale, ns);
}

bool RvizVisualTools::publishSpheres(const std::vector<geometry_msgs::Point>& points, colors color, double scale,
                                     const std::string& ns)
{
  return publishSpheres(points, color, uniformScale(scale * global_scale_), ns);
}

bool RvizVisualTools::publishSpheres(const std::vector<geometry_msgs::Point>& points, colors color, scales scale,
                                     const std::string& ns)
{
  return publishSpheres(points, color, getScale(scale), ns);
}

bool RvizVisualTools::publishSpheres(const std::vector<geometry_msgs::Point>& points, colors color,
                                     const geometry_msgs::Vector3& scale, const std::string& ns)
{
  const std_msgs::ColorRGBA this_color = getColor(color);
  spheres_marker_.color = this_color;
  return publishSpheres(points, std::vector<std_msgs::ColorRGBA>(points.size(), this_color), scale, ns);
}

bool RvizVisualTools::publishSpheres(const EigenSTL::vector_Vector3d& points, const std::vector<colors>& colors,
                                     scales scale, const std::string& ns)
{
  if (points.size() != colors.size())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "publishSpheres: " << points.size() << " points but " << colors.size()
                                                       << " colors");
    return false;
  }
  std::vector<geometry_msgs::Point> points_msg;
  std::vector<std_msgs::ColorRGBA> colors_msg;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    points_msg.push_back(convertPoint(points[i]));
    colors_msg.push_back(getColor(colors[i]));
  }
  return publishSpheres(points_msg, colors_msg, getScale(scale), ns);
}

bool RvizVisualTools::publishSpheres(const std::vector<geometry_msgs::Point>& points,
                                     const std::vector<std_msgs::ColorRGBA>& colors,
                                     const geometry_msgs::Vector3& scale, const std::string& ns)
{
  spheres_marker_.header.stamp = ros::Time();
  spheres_marker_.ns = ns;
  spheres_marker_.id++;
  spheres_marker_.scale = scale;
  spheres_marker_.points = points;
  spheres_marker_.colors = colors;
  return publishMarker(spheres_marker_);
}

bool RvizVisualTools::publishXArrow(const Eigen::Isometry3d& pose, colors color, scales scale, double length)
{
  return publishArrow(convertPose(pose), color, scale, length);
}

bool RvizVisualTools::publishXArrow(const geometry_msgs::Pose& pose, colors color, scales scale, double length)
{
  return publishArrow(pose, color, scale, length);
}

bool RvizVisualTools::publishXArrow(const geometry_msgs::PoseStamped& pose, colors color, scales scale, double length)
{
  return publishArrow(pose, color, scale, length);
}

namespace
{
// An arrow marker points along its pose's x: a y arrow turns z by +90 deg, a z arrow y by -90 deg
// (l. 1270, 1291)
const Eigen::AngleAxisd Y_ARROW_TURN(M_PI / 2, Eigen::Vector3d::UnitZ());
const Eigen::AngleAxisd Z_ARROW_TURN(-M_PI / 2, Eigen::Vector3d::UnitY());
}  // namespace

bool RvizVisualTools::publishYArrow(const Eigen::Isometry3d& pose, colors color, scales scale, double length)
{
  return publishArrow(convertPose(pose * Y_ARROW_TURN), color, scale, length);
}

bool RvizVisualTools::publishYArrow(const geometry_msgs::Pose& pose, colors color, scales scale, double length)
{
  return publishYArrow(convertPose(pose), color, scale, length);
}

bool RvizVisualTools::publishYArrow(const geometry_msgs::PoseStamped& pose, colors color, scales scale, double length)
{
  geometry_msgs::PoseStamped turned = pose;
  turned.pose = convertPose(convertPose(pose.pose) * Y_ARROW_TURN);
  return publishArrow(turned, color, scale, length);
}

bool RvizVisualTools::publishZArrow(const Eigen::Isometry3d& pose, colors color, scales scale, double length,
                                    std::size_t id)
{
  return publishArrow(convertPose(pose * Z_ARROW_TURN), color, scale, length, id);
}

bool RvizVisualTools::publishZArrow(const geometry_msgs::Pose& pose, colors color, scales scale, double length)
{
  return publishZArrow(convertPose(pose), color, scale, length);
}

bool RvizVisualTools::publishZArrow(const geometry_msgs::PoseStamped& pose, colors color, scales scale, double length)
{
  return publishZArrow(pose, color, scale, length, 0);
}

bool RvizVisualTools::publishZArrow(const geometry_msgs::PoseStamped& pose, colors color, scales scale, double length,
                                    std::size_t id)
{
  geometry_msgs::PoseStamped turned = pose;
  turned.pose = convertPose(convertPose(pose.pose) * Z_ARROW_TURN);
  return publishArrow(turned, color, scale, length, id);
}

bool RvizVisualTools::publishArrow(const Eigen::Isometry3d& pose, colors color, scales scale, double length,
                                   std::size_t id)
{
  return publishArrow(convertPose(pose), color, scale, length, id);
}

bool RvizVisualTools::publishArrow(const geometry_msgs::Pose& pose, colors color, scales scale, double length,
                                   std::size_t id)
{
  geometry_msgs::PoseStamped stamped;
  stamped.header.stamp = ros::Time::now();
  stamped.header.frame_id = base_frame_;
  stamped.pose = pose;
  return publishArrow(stamped, color, scale, length, id);
}

bool RvizVisualTools::publishArrow(const geometry_msgs::PoseStamped& pose, colors color, scales scale, double length,
                                   std::size_t id)
{
  // Pose arrows: scale.x is the length (ten times the size when length is 0), y and z the
  // shaft's size (l. 1324-1392)
  arrow_marker_.header = pose.header;
  takeId(arrow_marker_, id);
  arrow_marker_.points.clear();
  arrow_marker_.pose = pose.pose;
  arrow_marker_.color = getColor(color);
  arrow_marker_.scale = getScale(scale);
  arrow_marker_.scale.x = (length == 0) ? arrow_marker_.scale.x * ARROW_AUTO_LENGTH_FACTOR : length;
  publishMarker(arrow_marker_);
  arrow_marker_.header.frame_id = base_frame_;
  return true;
}

bool RvizVisualTools::publishArrow(const geometry_msgs::Point& start, const geometry_msgs::Point& end, colors color,
                                   scales scale, std::size_t id)
{
  // Point arrows: scale.x the shaft's diameter, y the head's, z the head's length (l. 1394-1425)
  arrow_marker_.header.stamp = ros::Time::now();
  arrow_marker_.header.frame_id = base_frame_;
  takeId(arrow_marker_, id);
  arrow_marker_.pose = getIdentityPose();
  arrow_marker_.points = { start, end };
  arrow_marker_.color = getColor(color);
  arrow_marker_.scale = getScale(scale);
  arrow_marker_.scale.y *= ARROW_HEAD_DIAMETER_FACTOR;
  arrow_marker_.scale.z *= ARROW_HEAD_LENGTH_FACTOR;
  const bool result = publishMarker(arrow_marker_);
  arrow_marker_.points.clear();
  return result;
}

bool RvizVisualTools::publishAxisLabeled(const Eigen::Isometry3d& pose, const std::string& label, scales scale,
                                         colors color)
{
  return publishAxisLabeled(convertPose(pose), label, scale, color);
}

bool RvizVisualTools::publishAxisLabeled(const geometry_msgs::Pose& pose, const std::string& label, scales scale,
                                         colors color)
{
  // The axis in the label's namespace, the text one size up, off the origin so that both show
  // (l. 1433-1445)
  publishAxis(pose, scale, label);
  geometry_msgs::Pose shifted = pose;
  shifted.position.x -= AXIS_LABEL_OFFSET;
  shifted.position.y -= AXIS_LABEL_OFFSET;
  shifted.position.z -= AXIS_LABEL_OFFSET;
  publishText(shifted, label, color, static_cast<scales>(static_cast<int>(scale) + 1), false);
  return true;
}

bool RvizVisualTools::publishAxis(const geometry_msgs::Pose& pose, scales scale, const std::string& ns)
{
  const double radius = getScale(scale).x;
  return publishAxis(pose, radius * AXIS_LENGTH_PER_RADIUS, radius, ns);
}

bool RvizVisualTools::publishAxis(const Eigen::Isometry3d& pose, scales scale, const std::string& ns)
{
  const double radius = getScale(scale).x;
  return publishAxis(pose, radius * AXIS_LENGTH_PER_RADIUS, radius, ns);
}

bool RvizVisualTools::publishAxis(const geometry_msgs::Pose& pose, double length, double radius, const std::string& ns)
{
  return publishAxis(convertPose(pose), length, radius, ns);
}

bool RvizVisualTools::publishAxis(const Eigen::Isometry3d& pose, double length, double radius, const std::string& ns)
{
  return publishAxisInternal(pose, length, radius, ns);
}

bool RvizVisualTools::publishAxisInternal(const Eigen::Isometry3d& pose, double length, double radius,
                                          const std::string& ns)
{
  // Three cylinders from the origin along x (red), y (green), z (blue): a cylinder marker lies
  // along its z, so x's is turned +90 deg about y and y's +90 deg about x (l. 1473-1494)
  const Eigen::Isometry3d x_cylinder =
      pose * Eigen::Translation3d(length / 2.0, 0, 0) * Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitY());
  const Eigen::Isometry3d y_cylinder =
      pose * Eigen::Translation3d(0, length / 2.0, 0) * Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitX());
  const Eigen::Isometry3d z_cylinder = pose * Eigen::Translation3d(0, 0, length / 2.0);
  publishCylinder(x_cylinder, RED, length, radius, ns);
  publishCylinder(y_cylinder, GREEN, length, radius, ns);
  publishCylinder(z_cylinder, BLUE, length, radius, ns);
  return true;
}

bool RvizVisualTools::publishAxisPath(const EigenSTL::vector_Isometry3d& path, scales scale, const std::string& ns)
{
  const double radius = getScale(scale).x;
  return publishAxisPath(path, radius * AXIS_LENGTH_PER_RADIUS, radius, ns);
}

bool RvizVisualTools::publishAxisPath(const EigenSTL::vector_Isometry3d& path, double length, double radius,
                                      const std::string& ns)
{
  for (const Eigen::Isometry3d& pose : path)
  {
    publishAxisInternal(pose, length, radius, ns);
  }
  return true;
}

bool RvizVisualTools::publishCylinder(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, colors color,
                                      scales scale, const std::string& ns)
{
  return publishCylinder(point1, point2, getColor(color), getScale(scale).x, ns);
}

bool RvizVisualTools::publishCylinder(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, colors color,
                                      double radius, const std::string& ns)
{
  return publishCylinder(point1, point2, getColor(color), radius, ns);
}

bool RvizVisualTools::publishCylinder(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2,
                                      const std_msgs::ColorRGBA& color, double radius, const std::string& ns)
{
  // Centred between the points, its z axis along point1 -> point2, as long as they are apart
  // (l. 1533-1553)
  const Eigen::Isometry3d along =
      getVectorBetweenPoints(getCenterPoint(point1, point2), point2) *
      Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY());
  return publishCylinder(convertPose(along), color, (point1 - point2).norm(), radius, ns);
}

bool RvizVisualTools::publishCylinder(const Eigen::Isometry3d& pose, colors color, double height, double radius,
                                      const std::string& ns)
{
  return publishCylinder(convertPose(pose), color, height, radius, ns);
}

bool RvizVisualTools::publishCylinder(const geometry_msgs::Pose& pose, colors color, double height, double radius,
                                      const std::string& ns)
{
  return publishCylinder(pose, getColor(color), height, radius, ns);
}

bool RvizVisualTools::publishCylinder(const geometry_msgs::Pose& pose, const std_msgs::ColorRGBA& color, double height,
                                      double radius, const std::string& ns)
{
  // scale.x and y are the diameter in rviz; upstream passes the radius there (l. 1579-1581)
  cylinder_marker_.header.stamp = ros::Time::now();
  cylinder_marker_.ns = ns;
  cylinder_marker_.id++;
  cylinder_marker_.pose = pose;
  cylinder_marker_.scale.x = radius;
  cylinder_marker_.scale.y = radius;
  cylinder_marker_.scale.z = height;
  cylinder_marker_.color = color;
  return publishMarker(cylinder_marker_);
}

bool RvizVisualTools::publishMesh(const Eigen::Isometry3d& pose, const std::string& file_name, colors color,
                                  double scale, const std::string& ns, std::size_t id)
{
  return publishMesh(convertPose(pose), file_name, color, scale, ns, id);
}

bool RvizVisualTools::publishMesh(const geometry_msgs::Pose& pose, const std::string& file_name, colors color,
                                  double scale, const std::string& ns, std::size_t id)
{
  mesh_marker_.header.stamp = ros::Time::now();
  takeId(mesh_marker_, id);
  mesh_marker_.mesh_resource = file_name;
  mesh_marker_.mesh_use_embedded_materials = 1u;
  mesh_marker_.pose = pose;
  mesh_marker_.scale = uniformScale(scale);
  mesh_marker_.ns = ns;
  mesh_marker_.color = getColor(color);
  return publishMarker(mesh_marker_);
}

bool RvizVisualTools::publishMesh(const Eigen::Isometry3d& pose, const shape_msgs::Mesh& mesh, colors color,
                                  double scale, const std::string& ns, std::size_t id)
{
  return publishMesh(convertPose(pose), mesh, color, scale, ns, id);
}

bool RvizVisualTools::publishMesh(const geometry_msgs::Pose& pose, const shape_msgs::Mesh& mesh, colors color,
                                  double scale, const std::string& ns, std::size_t id)
{
  // The mesh's triangles as a TRIANGLE_LIST (l. 1640-1677)
  triangle_marker_.header.stamp = ros::Time::now();
  takeId(triangle_marker_, id);
  triangle_marker_.points.clear();
  for (const shape_msgs::MeshTriangle& triangle : mesh.triangles)
  {
    for (uint32_t index : triangle.vertex_indices)
    {
      triangle_marker_.points.push_back(mesh.vertices.at(index));
    }
  }
  triangle_marker_.pose = pose;
  triangle_marker_.scale = uniformScale(scale);
  triangle_marker_.ns = ns;
  triangle_marker_.color = getColor(color);
  return publishMarker(triangle_marker_);
}

bool RvizVisualTools::publishCuboid(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, colors color)
{
  return publishCuboid(convertPoint(point1), convertPoint(point2), color);
}

namespace
{
// rviz does not draw a cube with a zero side: such a side is SMALL_SCALE (l. 1746-1758, 1780-1806)
double visibleSide(double side)
{
  return side <= 0.0 ? SMALL_SCALE : side;
}
}  // namespace

bool RvizVisualTools::publishCuboid(const geometry_msgs::Point& point1, const geometry_msgs::Point& point2,
                                    colors color, const std::string& ns, std::size_t id)
{
  // The axis-aligned box with these opposite corners (l. 1716-1762)
  cuboid_marker_.header.stamp = ros::Time::now();
  cuboid_marker_.ns = ns;
  takeId(cuboid_marker_, id);
  cuboid_marker_.color = getColor(color);
  geometry_msgs::Pose pose = getIdentityPose();
  pose.position.x = (point1.x + point2.x) / 2.0;
  pose.position.y = (point1.y + point2.y) / 2.0;
  pose.position.z = (point1.z + point2.z) / 2.0;
  cuboid_marker_.pose = pose;
  cuboid_marker_.scale.x = visibleSide(std::fabs(point1.x - point2.x));
  cuboid_marker_.scale.y = visibleSide(std::fabs(point1.y - point2.y));
  cuboid_marker_.scale.z = visibleSide(std::fabs(point1.z - point2.z));
  return publishMarker(cuboid_marker_);
}

bool RvizVisualTools::publishCuboid(const Eigen::Isometry3d& pose, double depth, double width, double height,
                                    colors color)
{
  return publishCuboid(convertPose(pose), depth, width, height, color);
}

bool RvizVisualTools::publishCuboid(const geometry_msgs::Pose& pose, double depth, double width, double height,
                                    colors color)
{
  // Keeps the namespace of the last cuboid (upstream does not set it here, l. 1770-1809)
  cuboid_marker_.header.stamp = ros::Time::now();
  cuboid_marker_.id++;
  cuboid_marker_.color = getColor(color);
  cuboid_marker_.pose = pose;
  cuboid_marker_.scale.x = visibleSide(depth);
  cuboid_marker_.scale.y = visibleSide(width);
  cuboid_marker_.scale.z = visibleSide(height);
  return publishMarker(cuboid_marker_);
}

bool RvizVisualTools::publishCuboid(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size, colors color)
{
  return publishCuboid(pose, size.x(), size.y(), size.z(), color);
}

bool RvizVisualTools::publishCuboid(const geometry_msgs::Pose& pose, const geometry_msgs::Vector3& size, colors color)
{
  return publishCuboid(pose, size.x, size.y, size.z, color);
}

bool RvizVisualTools::publishLine(const Eigen::Isometry3d& point1, const Eigen::Isometry3d& point2, colors color,
                                  scales scale)
{
  return publishLine(convertPoseToPoint(point1), convertPoseToPoint(point2), color, scale);
}

bool RvizVisualTools::publishLine(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, colors color,
                                  scales scale)
{
  return publishLine(convertPoint(point1), convertPoint(point2), color, scale);
}

bool RvizVisualTools::publishLine(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, colors color,
                                  double radius)
{
  return publishLine(convertPoint(point1), convertPoint(point2), getColor(color), uniformScale(radius * global_scale_));
}

bool RvizVisualTools::publishLine(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2,
                                  const std_msgs::ColorRGBA& color, scales scale)
{
  return publishLine(convertPoint(point1), convertPoint(point2), color, scale);
}

bool RvizVisualTools::publishLine(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2,
                                  const std_msgs::ColorRGBA& color, double radius)
{
  return publishLine(convertPoint(point1), convertPoint(point2), color, uniformScale(radius * global_scale_));
}

bool RvizVisualTools::publishLine(const geometry_msgs::Point& point1, const geometry_msgs::Point& point2, colors color,
                                  scales scale)
{
  return publishLine(point1, point2, getColor(color), scale);
}

bool RvizVisualTools::publishLine(const geometry_msgs::Point& point1, const geometry_msgs::Point& point2,
                                  const std_msgs::ColorRGBA& color, scales scale)
{
  return publishLine(point1, point2, color, getScale(scale));
}

bool RvizVisualTools::publishLine(const geometry_msgs::Point& point1, const geometry_msgs::Point& point2,
                                  const std_msgs::ColorRGBA& color, const geometry_msgs::Vector3& scale)
{
  // A line's width is scale.x; rviz ignores y and z for lines (l. 1870-1888)
  line_strip_marker_.header.stamp = ros::Time::now();
  line_strip_marker_.id++;
  line_strip_marker_.color = color;
  line_strip_marker_.scale = scale;
  line_strip_marker_.scale.y = 0;
  line_strip_marker_.scale.z = 0;
  line_strip_marker_.points = { point1, point2 };
  line_strip_marker_.colors.clear();
  return publishMarker(line_strip_marker_);
}

bool RvizVisualTools::publishLines(const EigenSTL::vector_Vector3d& aPoints, const EigenSTL::vector_Vector3d& bPoints,
                                   const std::vector<colors>& colors, scales scale)
{
  if (aPoints.size() != bPoints.size() || bPoints.size() != colors.size())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "publishLines: mismatching vector sizes: aPoints, bPoints, and colors");
    return false;
  }
  std::vector<geometry_msgs::Point> a_msg;
  std::vector<geometry_msgs::Point> b_msg;
  std::vector<std_msgs::ColorRGBA> colors_msg;
  for (std::size_t i = 0; i < aPoints.size(); ++i)
  {
    a_msg.push_back(convertPoint(aPoints[i]));
    b_msg.push_back(convertPoint(bPoints[i]));
    colors_msg.push_back(getColor(colors[i]));
  }
  return publishLines(a_msg, b_msg, colors_msg, getScale(scale));
}

bool RvizVisualTools::publishLines(const std::vector<geometry_msgs::Point>& aPoints,
                                   const std::vector<geometry_msgs::Point>& bPoints,
                                   const std::vector<std_msgs::ColorRGBA>& colors, const geometry_msgs::Vector3& scale)
{
  if (aPoints.size() != bPoints.size() || bPoints.size() != colors.size())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "publishLines: mismatching vector sizes: aPoints, bPoints, and colors");
    return false;
  }
  // Namespace "Line Array" (l. 1921)
  line_list_marker_.header.stamp = ros::Time();
  line_list_marker_.ns = "Line Array";
  line_list_marker_.id++;
  line_list_marker_.scale = scale;
  line_list_marker_.scale.y = 0;
  line_list_marker_.scale.z = 0;
  line_list_marker_.points.clear();
  line_list_marker_.colors.clear();
  for (std::size_t i = 0; i < aPoints.size(); ++i)
  {
    line_list_marker_.points.push_back(aPoints[i]);
    line_list_marker_.points.push_back(bPoints[i]);
    line_list_marker_.colors.push_back(colors[i]);
    line_list_marker_.colors.push_back(colors[i]);
  }
  return publishMarker(line_list_marker_);
}

bool RvizVisualTools::publishLineStrip(const std::vector<geometry_msgs::Point>& path, colors color, scales scale,
                                       const std::string& ns)
{
  // Upstream sends each segment's two ends in turn (l. 1951-1985)
  if (path.size() < 2)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Skipping path because " << path.size() << " points passed in.");
    return true;
  }
  line_strip_marker_.header.stamp = ros::Time();
  line_strip_marker_.ns = ns;
  line_strip_marker_.id++;
  const std_msgs::ColorRGBA this_color = getColor(color);
  line_strip_marker_.scale = getScale(scale);
  line_strip_marker_.scale.y = 0;
  line_strip_marker_.scale.z = 0;
  line_strip_marker_.color = this_color;
  line_strip_marker_.points.clear();
  line_strip_marker_.colors.clear();
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    line_strip_marker_.points.push_back(path[i - 1]);
    line_strip_marker_.points.push_back(path[i]);
    line_strip_marker_.colors.push_back(this_color);
    line_strip_marker_.colors.push_back(this_color);
  }
  return publishMarker(line_strip_marker_);
}

bool RvizVisualTools::publishPath(const std::vector<geometry_msgs::Pose>& path, colors color, scales scale,
                                  const std::string& ns)
{
  std::vector<geometry_msgs::Point> points;
  for (const geometry_msgs::Pose& pose : path)
  {
    points.push_back(pose.position);
  }
  return publishPath(points, color, getScale(scale).x, ns);
}

bool RvizVisualTools::publishPath(const std::vector<geometry_msgs::Point>& path, colors color, scales scale,
                                  const std::string& ns)
{
  return publishPath(path, color, getScale(scale).x, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Isometry3d& path, colors color, scales scale,
                                  const std::string& ns)
{
  return publishPath(path, color, getScale(scale).x, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Vector3d& path, colors color, scales scale,
                                  const std::string& ns)
{
  return publishPath(path, color, getScale(scale).x, ns);
}

bool RvizVisualTools::publishPath(const std::vector<geometry_msgs::Point>& path, colors color, double radius,
                                  const std::string& ns)
{
  EigenSTL::vector_Vector3d points;
  for (const geometry_msgs::Point& point : path)
  {
    points.push_back(convertPoint(point));
  }
  return publishPath(points, color, radius, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Isometry3d& path, colors color, double radius,
                                  const std::string& ns)
{
  EigenSTL::vector_Vector3d points;
  for (const Eigen::Isometry3d& pose : path)
  {
    points.push_back(pose.translation());
  }
  return publishPath(points, color, radius, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Vector3d& path, colors color, double radius,
                                  const std::string& ns)
{
  return publishPath(path, std::vector<std_msgs::ColorRGBA>(path.size(), getColor(color)), radius, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Vector3d& path, const std::vector<colors>& colors,
                                  double radius, const std::string& ns)
{
  std::vector<std_msgs::ColorRGBA> colors_msg;
  for (std::size_t i = 0; i < colors.size(); ++i)
  {
    colors_msg.push_back(getColor(colors[i]));
  }
  return publishPath(path, colors_msg, radius, ns);
}

bool RvizVisualTools::publishPath(const EigenSTL::vector_Vector3d& path, const std::vector<std_msgs::ColorRGBA>& colors,
                                  double radius, const std::string& ns)
{
  // One cylinder per segment, coloured by its end point's colour (l. 2017-2119)
  if (path.size() < 2)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Skipping path because " << path.size() << " points passed in.");
    return false;
  }
  if (path.size() != colors.size())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME,
                           "Skipping path because " << path.size() << " different from " << colors.size() << ".");
    return false;
  }
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    publishCylinder(path[i - 1], path[i], colors[i], radius, ns);
  }
  return true;
}

bool RvizVisualTools::publishPolygon(const geometry_msgs::Polygon& polygon, colors color, scales scale,
                                     const std::string& ns)
{
  // The closed outline: a path back to the first point (l. 2121-2143)
  std::vector<geometry_msgs::Point> points;
  for (const geometry_msgs::Point32& corner : polygon.points)
  {
    points.push_back(convertPoint(convertPoint32(corner)));
  }
  if (!points.empty())
  {
    points.push_back(points.front());
  }
  return publishPath(points, color, scale, ns);
}

namespace
{
void addLine(visualization_msgs::Marker& marker, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
             const std_msgs::ColorRGBA& color)
{
  marker.points.push_back(RvizVisualTools::convertPoint(a));
  marker.points.push_back(RvizVisualTools::convertPoint(b));
  marker.colors.push_back(color);
  marker.colors.push_back(color);
}
}  // namespace

bool RvizVisualTools::publishWireframeCuboid(const Eigen::Isometry3d& pose, double depth, double width, double height,
                                             colors color, const std::string& ns, std::size_t id)
{
  const Eigen::Vector3d half(depth / 2, width / 2, height / 2);
  return publishWireframeCuboid(pose, -half, half, color, ns, id);
}

bool RvizVisualTools::publishWireframeCuboid(const Eigen::Isometry3d& pose, const Eigen::Vector3d& min_point,
                                             const Eigen::Vector3d& max_point, colors color, const std::string& ns,
                                             std::size_t id)
{
  // The twelve edges of the box as a LINE_LIST, XXSMALL wide (l. 2154-2261)
  line_list_marker_.header.stamp = ros::Time();
  line_list_marker_.ns = ns;
  takeId(line_list_marker_, id);
  const std_msgs::ColorRGBA this_color = getColor(color);
  line_list_marker_.scale = getScale(XXSMALL);
  line_list_marker_.scale.y = 0;
  line_list_marker_.scale.z = 0;
  line_list_marker_.color = this_color;
  line_list_marker_.points.clear();
  line_list_marker_.colors.clear();
  auto corner = [&](bool x, bool y, bool z) {
    return pose * Eigen::Vector3d(x ? max_point.x() : min_point.x(), y ? max_point.y() : min_point.y(),
                                  z ? max_point.z() : min_point.z());
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int other = 0; other < 4; ++other)
    {
      // The edge along `axis`, the other two coordinates at min or max
      bool low[3];
      bool high[3];
      const int first = (axis + 1) % 3;
      const int second = (axis + 2) % 3;
      low[axis] = false;
      high[axis] = true;
      low[first] = high[first] = (other & 1) != 0;
      low[second] = high[second] = (other & 2) != 0;
      addLine(line_list_marker_, corner(low[0], low[1], low[2]), corner(high[0], high[1], high[2]), this_color);
    }
  }
  return publishMarker(line_list_marker_);
}

bool RvizVisualTools::publishWireframeRectangle(const Eigen::Isometry3d& pose, double height, double width,
                                                colors color, scales scale, std::size_t id)
{
  // Width along x, height along y, in the pose's xy plane (l. 2263-2322)
  takeId(line_list_marker_, id);
  const Eigen::Vector3d p1(-width / 2.0, -height / 2.0, 0.0);
  const Eigen::Vector3d p2(-width / 2.0, height / 2.0, 0.0);
  const Eigen::Vector3d p3(width / 2.0, height / 2.0, 0.0);
  const Eigen::Vector3d p4(width / 2.0, -height / 2.0, 0.0);
  // The four-point overload takes a new id itself: step back so that this call's id is kept
  line_list_marker_.id--;
  return publishWireframeRectangle(pose, p1, p2, p3, p4, color, scale);
}

bool RvizVisualTools::publishWireframeRectangle(const Eigen::Isometry3d& pose, const Eigen::Vector3d& p1_in,
                                                const Eigen::Vector3d& p2_in, const Eigen::Vector3d& p3_in,
                                                const Eigen::Vector3d& p4_in, colors color, scales scale)
{
  line_list_marker_.header.stamp = ros::Time();
  line_list_marker_.ns = "Wireframe Rectangle";
  line_list_marker_.id++;
  const std_msgs::ColorRGBA this_color = getColor(color);
  line_list_marker_.scale = getScale(scale, WIREFRAME_RECTANGLE_SCALE);
  line_list_marker_.scale.y = 0;
  line_list_marker_.scale.z = 0;
  line_list_marker_.color = this_color;
  line_list_marker_.points.clear();
  line_list_marker_.colors.clear();
  const Eigen::Vector3d p1 = pose * p1_in;
  const Eigen::Vector3d p2 = pose * p2_in;
  const Eigen::Vector3d p3 = pose * p3_in;
  const Eigen::Vector3d p4 = pose * p4_in;
  addLine(line_list_marker_, p1, p2, this_color);
  addLine(line_list_marker_, p2, p3, this_color);
  addLine(line_list_marker_, p3, p4, this_color);
  addLine(line_list_marker_, p4, p1, this_color);
  return publishMarker(line_list_marker_);
}

bool RvizVisualTools::publishText(const Eigen::Isometry3d& pose, const std::string& text, colors color, scales scale,
                                  bool static_id)
{
  return publishText(convertPose(pose), text, color, getScale(scale), static_id);
}

bool RvizVisualTools::publishText(const Eigen::Isometry3d& pose, const std::string& text, colors color,
                                  const geometry_msgs::Vector3 scale, bool static_id)
{
  return publishText(convertPose(pose), text, color, scale, static_id);
}

bool RvizVisualTools::publishText(const geometry_msgs::Pose& pose, const std::string& text, colors color, scales scale,
                                  bool static_id)
{
  return publishText(pose, text, color, getScale(scale), static_id);
}

bool RvizVisualTools::publishText(const geometry_msgs::Pose& pose, const std::string& text, colors color,
                                  const geometry_msgs::Vector3 scale, bool static_id)
{
  // A static text always has id 0 (and leaves the count alone); only scale.z, the height of a
  // capital, counts for text (l. 2502-2534)
  const int32_t counted_id = text_marker_.id;
  text_marker_.id = static_id ? 0 : counted_id + 1;
  text_marker_.header.stamp = ros::Time::now();
  text_marker_.header.frame_id = base_frame_;
  text_marker_.text = text;
  text_marker_.pose = pose;
  text_marker_.color = getColor(color);
  text_marker_.scale = scale;
  text_marker_.scale.x = 0;
  text_marker_.scale.y = 0;
  publishMarker(text_marker_);
  if (static_id)
  {
    text_marker_.id = counted_id;
  }
  return true;
}

geometry_msgs::Pose RvizVisualTools::convertPose(const Eigen::Isometry3d& pose)
{
  geometry_msgs::Pose msg;
  convertPoseSafe(pose, msg);
  return msg;
}

void RvizVisualTools::convertPoseSafe(const Eigen::Isometry3d& pose, geometry_msgs::Pose& pose_msg)
{
  const Eigen::Quaterniond q(pose.rotation());
  pose_msg.position.x = pose.translation().x();
  pose_msg.position.y = pose.translation().y();
  pose_msg.position.z = pose.translation().z();
  pose_msg.orientation.x = q.x();
  pose_msg.orientation.y = q.y();
  pose_msg.orientation.z = q.z();
  pose_msg.orientation.w = q.w();
}

Eigen::Isometry3d RvizVisualTools::convertPose(const geometry_msgs::Pose& pose)
{
  Eigen::Isometry3d result;
  convertPoseSafe(pose, result);
  return result;
}

void RvizVisualTools::convertPoseSafe(const geometry_msgs::Pose& pose_msg, Eigen::Isometry3d& pose)
{
  // As tf2_eigen's fromMsg: the quaternion is taken as given (normalised by Eigen's rotation)
  const Eigen::Quaterniond q(pose_msg.orientation.w, pose_msg.orientation.x, pose_msg.orientation.y,
                             pose_msg.orientation.z);
  pose = Eigen::Translation3d(pose_msg.position.x, pose_msg.position.y, pose_msg.position.z) * q;
}

Eigen::Isometry3d RvizVisualTools::convertPoint32ToPose(const geometry_msgs::Point32& point)
{
  return convertPointToPose(convertPoint32(point));
}

geometry_msgs::Pose RvizVisualTools::convertPointToPose(const geometry_msgs::Point& point)
{
  geometry_msgs::Pose pose = getIdentityPose();
  pose.position = point;
  return pose;
}

Eigen::Isometry3d RvizVisualTools::convertPointToPose(const Eigen::Vector3d& point)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = point;
  return pose;
}

geometry_msgs::Point RvizVisualTools::convertPoseToPoint(const Eigen::Isometry3d& pose)
{
  return convertPoint(Eigen::Vector3d(pose.translation()));
}

Eigen::Vector3d RvizVisualTools::convertPoint(const geometry_msgs::Point& point)
{
  return Eigen::Vector3d(point.x, point.y, point.z);
}

Eigen::Vector3d RvizVisualTools::convertPoint32(const geometry_msgs::Point32& point)
{
  return Eigen::Vector3d(point.x, point.y, point.z);
}

geometry_msgs::Point32 RvizVisualTools::convertPoint32(const Eigen::Vector3d& point)
{
  geometry_msgs::Point32 msg;
  msg.x = point.x();
  msg.y = point.y();
  msg.z = point.z();
  return msg;
}

geometry_msgs::Point RvizVisualTools::convertPoint(const geometry_msgs::Vector3& point)
{
  geometry_msgs::Point msg;
  msg.x = point.x;
  msg.y = point.y;
  msg.z = point.z;
  return msg;
}

geometry_msgs::Point RvizVisualTools::convertPoint(const Eigen::Vector3d& point)
{
  geometry_msgs::Point msg;
  msg.x = point.x();
  msg.y = point.y();
  msg.z = point.z();
  return msg;
}

Eigen::Isometry3d RvizVisualTools::convertFromXYZRPY(double tx, double ty, double tz, double rx, double ry, double rz,
                                                     EulerConvention convention)
{
  const Eigen::Translation3d t(tx, ty, tz);
  const Eigen::AngleAxisd about_x(rx, Eigen::Vector3d::UnitX());
  const Eigen::AngleAxisd about_y(ry, Eigen::Vector3d::UnitY());
  const Eigen::AngleAxisd about_z(rz, Eigen::Vector3d::UnitZ());
  switch (convention)
  {
    case XYZ:
      return Eigen::Isometry3d(t * about_x * about_y * about_z);
    case ZYX:
      return Eigen::Isometry3d(t * about_z * about_y * about_x);
    case ZXZ:
      // Upstream turns about z by rz twice (l. 2660-2663; ry unused): kept, code relies on it
      return Eigen::Isometry3d(t * about_z * about_x * about_z);
  }
  ROS_ERROR_STREAM_NAMED(LOGNAME, "Invalid euler convention entry " << convention);
  return Eigen::Isometry3d::Identity();
}

Eigen::Isometry3d RvizVisualTools::convertFromXYZRPY(const std::vector<double>& transform6, EulerConvention convention)
{
  const std::size_t xyzrpy_size = 6;
  if (transform6.size() != xyzrpy_size)
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "Incorrect number of variables passed for 6-size transform");
    throw std::runtime_error("Incorrect number of variables passed for 6-size transform");
  }
  return convertFromXYZRPY(transform6[0], transform6[1], transform6[2], transform6[3], transform6[4], transform6[5],
                           convention);
}

void RvizVisualTools::convertToXYZRPY(const Eigen::Isometry3d& pose, std::vector<double>& xyzrpy)
{
  xyzrpy.resize(6);
  convertToXYZRPY(pose, xyzrpy[0], xyzrpy[1], xyzrpy[2], xyzrpy[3], xyzrpy[4], xyzrpy[5]);
}

void RvizVisualTools::convertToXYZRPY(const Eigen::Isometry3d& pose, double& x, double& y, double& z, double& roll,
                                      double& pitch, double& yaw)
{
  // Euler angles about x, then y, then z of the moving frame (Eigen's eulerAngles(0, 1, 2),
  // l. 2689-2701)
  x = pose.translation().x();
  y = pose.translation().y();
  z = pose.translation().z();
  const Eigen::Vector3d angles = pose.rotation().eulerAngles(0, 1, 2);
  roll = angles[0];
  pitch = angles[1];
  yaw = angles[2];
}

void RvizVisualTools::generateRandomPose(geometry_msgs::Pose& pose, RandomPoseBounds pose_bounds)
{
  Eigen::Isometry3d pose_eigen;
  generateRandomPose(pose_eigen, pose_bounds);
  pose = convertPose(pose_eigen);
}

void RvizVisualTools::generateRandomCuboid(geometry_msgs::Pose& cuboid_pose, double& depth, double& width,
                                           double& height, RandomPoseBounds pose_bounds,
                                           RandomCuboidBounds cuboid_bounds)
{
  depth = fRand(cuboid_bounds.cuboid_size_min_, cuboid_bounds.cuboid_size_max_);
  width = fRand(cuboid_bounds.cuboid_size_min_, cuboid_bounds.cuboid_size_max_);
  height = fRand(cuboid_bounds.cuboid_size_min_, cuboid_bounds.cuboid_size_max_);
  generateRandomPose(cuboid_pose, pose_bounds);
}

void RvizVisualTools::generateRandomPose(Eigen::Isometry3d& pose, RandomPoseBounds pose_bounds)
{
  // Elevation within [0, pi], azimuth within [0, 2 pi]; the rotation is an angle about an axis
  // drawn by elevation and azimuth (l. 2723-2769)
  if (pose_bounds.elevation_min_ < 0)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "min elevation bound < 0, setting equal to 0");
    pose_bounds.elevation_min_ = 0;
  }
  if (pose_bounds.elevation_max_ > M_PI)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "max elevation bound > pi, setting equal to pi ");
    pose_bounds.elevation_max_ = M_PI;
  }
  if (pose_bounds.azimuth_min_ < 0)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "min azimuth bound < 0, setting equal to 0");
    pose_bounds.azimuth_min_ = 0;
  }
  if (pose_bounds.azimuth_max_ > 2 * M_PI)
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "max azimuth bound > 2 pi, setting equal to 2 pi ");
    pose_bounds.azimuth_max_ = 2 * M_PI;
  }
  const Eigen::Vector3d position(dRand(pose_bounds.x_min_, pose_bounds.x_max_),
                                 dRand(pose_bounds.y_min_, pose_bounds.y_max_),
                                 dRand(pose_bounds.z_min_, pose_bounds.z_max_));
  const double angle = dRand(pose_bounds.angle_min_, pose_bounds.angle_max_);
  const double elevation = dRand(pose_bounds.elevation_min_, pose_bounds.elevation_max_);
  const double azimuth = dRand(pose_bounds.azimuth_min_, pose_bounds.azimuth_max_);
  const Eigen::Vector3d axis(std::sin(elevation) * std::cos(azimuth), std::sin(elevation) * std::sin(azimuth),
                             std::cos(elevation));
  pose = Eigen::Translation3d(position) * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

geometry_msgs::Pose RvizVisualTools::getIdentityPose()
{
  geometry_msgs::Pose pose;
  pose.orientation.w = 1;
  return pose;
}

bool RvizVisualTools::posesEqual(const Eigen::Isometry3d& pose1, const Eigen::Isometry3d& pose2, double threshold)
{
  // Every entry of the 4x4 matrices within threshold (l. 2787-2800)
  return ((pose1.matrix() - pose2.matrix()).array().abs() <= threshold).all();
}

double RvizVisualTools::dRand(double min, double max)
{
  const double d = static_cast<double>(std::rand()) / RAND_MAX;
  return min + d * (max - min);
}

float RvizVisualTools::fRand(float min, float max)
{
  const float d = static_cast<float>(std::rand()) / RAND_MAX;
  return min + d * (max - min);
}

int RvizVisualTools::iRand(int min, int max)
{
  // Uniform on [min, max]: draws above the last whole multiple of the range are drawn again
  const int n = max - min + 1;
  const int remainder = RAND_MAX % n;
  int x;
  do
  {
    x = std::rand();
  } while (x >= RAND_MAX - remainder);
  return min + x % n;
}

void RvizVisualTools::printTranslation(const Eigen::Vector3d& translation)
{
  std::cout << "T.xyz = [" << translation.x() << ", " << translation.y() << ", " << translation.z() << "]" << std::endl;
}

void RvizVisualTools::printTransform(const Eigen::Isometry3d& transform)
{
  const Eigen::Quaterniond q(transform.rotation());
  std::cout << "T.xyz = [" << transform.translation().x() << ", " << transform.translation().y() << ", "
            << transform.translation().z() << "], Q.xyzw = [" << q.x() << ", " << q.y() << ", " << q.z() << ", "
            << q.w() << "]" << std::endl;
}

void RvizVisualTools::printTransformRPY(const Eigen::Isometry3d& transform)
{
  const Eigen::Vector3d angles = transform.rotation().eulerAngles(0, 1, 2);
  std::cout << "transform: [" << transform.translation().x() << ", " << transform.translation().y() << ", "
            << transform.translation().z() << ", " << angles[0] << ", " << angles[1] << ", " << angles[2] << "]\n";
}

void RvizVisualTools::printTransformFull(const Eigen::Isometry3d& transform)
{
  std::cout << "T.xyz = [" << transform.translation().x() << ", " << transform.translation().y() << ", "
            << transform.translation().z() << "], R = \n"
            << transform.rotation() << "\n";
}

void RvizVisualTools::prompt(const std::string& msg)
{
  getRemoteControl()->waitForNextStep(msg);
}

RemoteControlPtr& RvizVisualTools::getRemoteControl()
{
  if (!remote_control_)
  {
    loadRemoteControl();
  }
  return remote_control_;
}

void RvizVisualTools::loadRemoteControl()
{
  if (!remote_control_)
  {
    remote_control_ = std::make_shared<RemoteControl>(nh_);
    ros::spinOnce();
  }
}

}  // namespace rviz_visual_tools
