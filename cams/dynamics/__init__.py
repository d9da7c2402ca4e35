"""The follower's dynamics: spring, contact force, jamming force, jump speed, rigid impacts."""
