package touchline.transport.nao;

import java.util.Set;

/**
 * A walk command as {@code ALMotion.moveToward} takes it: normalised velocities in -1..1,
 * x forward, y left, theta counter-clockwise. Built from held keys (W/S forward/back, A/D
 * sideways, Q/E turn, at a chosen speed) or from gamepad axes (with a dead zone so a
 * resting stick does not creep the robot).
 */
public record WalkInput(float x, float y, float theta) {

    public static final WalkInput STOP = new WalkInput(0, 0, 0);
    /** Stick deflections below this count as zero. */
    public static final float DEAD_ZONE = 0.15f;

    public WalkInput {
        x = clamp(x);
        y = clamp(y);
        theta = clamp(theta);
    }

    /** Keys are upper-case letters as typed: W S A D Q E. */
    public static WalkInput fromKeys(Set<Character> held, float speed) {
        float s = clamp(Math.abs(speed));
        float x = (held.contains('W') ? s : 0) - (held.contains('S') ? s : 0);
        float y = (held.contains('A') ? s : 0) - (held.contains('D') ? s : 0);
        float t = (held.contains('Q') ? s : 0) - (held.contains('E') ? s : 0);
        return new WalkInput(x, y, t);
    }

    /** Gamepad: left stick up/left and right stick left are positive (pass axes already in that sense). */
    public static WalkInput fromAxes(float forward, float left, float turnLeft) {
        return new WalkInput(deadZone(forward), deadZone(left), deadZone(turnLeft));
    }

    public boolean isStop() {
        return x == 0 && y == 0 && theta == 0;
    }

    private static float deadZone(float v) {
        return Math.abs(v) < DEAD_ZONE ? 0 : v;
    }

    private static float clamp(float v) {
        if (Float.isNaN(v)) {
            return 0;
        }
        return Math.max(-1, Math.min(1, v));
    }
}
