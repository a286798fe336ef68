package glint.ui;

import glint.math.Quaternion;
import glint.math.Vector3d;
import glint.scene.Camera;

/**
 * Flies the camera: a position and a unit quaternion, moved by how long each key was held. All
 * motion is in the camera's own frame (right +x, up +y, forward +z): W flies where the camera looks,
 * the arrows turn about its own up and right axes, Q and E roll about its forward axis. Turns compose
 * as quaternions, so there is no gimbal lock, and the quaternion is re-normalised on every update so
 * that it stays unit however long one flies.
 */
public final class CameraController {

    /** Shift multiplies the flying speed by this. */
    public static final double FAST_FACTOR = 4;
    /** One wheel notch multiplies (towards the screen) or divides the flying speed by this. */
    public static final double WHEEL_FACTOR = 1.25;
    /** Degrees the camera turns per pixel of mouse drag. */
    public static final double DRAG_DEGREES_PER_PIXEL = 0.2;
    /** The wheel changes the speed by at most this factor either way. */
    static final double SPEED_FACTOR_LIMIT = 1024;

    private Vector3d position;
    private Quaternion orientation;
    private double fovDegrees;
    private double moveSpeed;
    private double turnSpeedDegrees;
    private double speedFactor = 1;

    /**
     * @param start            the initial pose and field of view
     * @param moveSpeed        scene units per second
     * @param turnSpeedDegrees degrees per second
     */
    public CameraController(Camera start, double moveSpeed, double turnSpeedDegrees) {
        reset(start);
        setSpeeds(moveSpeed, turnSpeedDegrees);
    }

    /** Puts the camera at a pose (for example the one of a reloaded scene). */
    public void reset(Camera camera) {
        this.position = camera.position();
        this.orientation = camera.orientation().normalize();
        this.fovDegrees = camera.fovDegrees();
    }

    public void setSpeeds(double newMoveSpeed, double newTurnSpeedDegrees) {
        this.moveSpeed = newMoveSpeed;
        this.turnSpeedDegrees = newTurnSpeedDegrees;
    }

    /** The camera now. */
    public Camera camera() {
        return new Camera(position, orientation, fovDegrees);
    }

    /** The flying speed now (config move_speed times the wheel's factor), without Shift. */
    public double speed() {
        return moveSpeed * speedFactor;
    }

    /** Applies one interval of input; returns whether the camera's pose changed. */
    public boolean apply(InputFrame in) {
        if (in.wheelNotches() != 0) {
            speedFactor *= Math.pow(WHEEL_FACTOR, -in.wheelNotches());
            speedFactor = Math.max(1 / SPEED_FACTOR_LIMIT, Math.min(SPEED_FACTOR_LIMIT, speedFactor));
        }
        boolean turned = turn(in);
        boolean moved = move(in);
        return turned || moved;
    }

    private boolean turn(InputFrame in) {
        double rate = Math.toRadians(turnSpeedDegrees);
        double drag = Math.toRadians(DRAG_DEGREES_PER_PIXEL);
        double yaw = rate * (in.seconds(Action.YAW_RIGHT) - in.seconds(Action.YAW_LEFT)) + drag * in.dragX();
        double pitchUp = rate * (in.seconds(Action.PITCH_UP) - in.seconds(Action.PITCH_DOWN)) - drag * in.dragY();
        double rollLeft = rate * (in.seconds(Action.ROLL_LEFT) - in.seconds(Action.ROLL_RIGHT));
        // In the camera frame: +yaw about +y turns forward towards right; looking up is a negative
        // turn about +x; rolling left (right side up) is a positive turn about +z.
        Vector3d rotation = new Vector3d(-pitchUp, yaw, rollLeft);
        double angle = rotation.length();
        if (angle == 0) {
            return false;
        }
        orientation = orientation.multiply(Quaternion.fromAxisAngle(rotation, angle)).normalize();
        return true;
    }

    private boolean move(InputFrame in) {
        double speed = speed() * (in.fast() ? FAST_FACTOR : 1);
        Vector3d local = new Vector3d(
                in.seconds(Action.RIGHT) - in.seconds(Action.LEFT),
                in.seconds(Action.UP) - in.seconds(Action.DOWN),
                in.seconds(Action.FORWARD) - in.seconds(Action.BACK)).scale(speed);
        if (local.x() == 0 && local.y() == 0 && local.z() == 0) {
            return false;
        }
        position = position.add(orientation.rotate(local));
        return true;
    }
}
