"""The controller manager's services, as a client sees them."""
from __future__ import annotations

import rospy
from controller_manager_msgs.srv import (ListControllers, LoadController, SwitchController,
                                         UnloadController)

STRICT = 2


class ControllerManager:
    def __init__(self, namespace: str):
        base = rospy.resolve_name("controller_manager", namespace) if namespace else \
            rospy.resolve_name("controller_manager")
        self.base = base
        self.load_service = f"{base}/load_controller"
        self.load = rospy.ServiceProxy(self.load_service, LoadController)
        self.unload = rospy.ServiceProxy(f"{base}/unload_controller", UnloadController)
        self.switch = rospy.ServiceProxy(f"{base}/switch_controller", SwitchController)
        self.list = rospy.ServiceProxy(f"{base}/list_controllers", ListControllers)

    def wait(self, timeout: float) -> bool:
        try:
            rospy.wait_for_service(self.load_service, timeout=timeout if timeout > 0 else None)
            return True
        except rospy.ROSException:
            return False

    def start(self, names) -> bool:
        return self.switch(list(names), [], STRICT, False, 0.0).ok

    def stop(self, names) -> bool:
        return self.switch([], list(names), STRICT, False, 0.0).ok
