"""The cam in its machine: the linkage, the cycle's timing, kinetostatics and the flywheel."""
