package touchline.model;

/**
 * Where one frame lies in another, in the plane: the child frame's origin at ({@code x},
 * {@code y}) metres of the parent and turned by {@code yaw} radians (REP 103: x forward, y
 * left, counter-clockwise). A 3D ROS transform is read as its x, y and the yaw of its
 * quaternion ({@link #of}); height, roll and pitch do not matter on the field. Pure.
 */
public record Transform2D(double x, double y, double yaw) {

    public static final Transform2D IDENTITY = new Transform2D(0, 0, 0);

    /** A ROS translation and rotation (quaternion x, y, z, w) in the plane. */
    public static Transform2D of(double x, double y, double qx, double qy, double qz, double qw) {
        double yaw = Math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz));
        return new Transform2D(x, y, Double.isFinite(yaw) ? yaw : 0);
    }

    /** This transform followed by {@code inner}: parent←child of this and child←grandchild of {@code inner} give parent←grandchild. */
    public Transform2D then(Transform2D inner) {
        double c = Math.cos(yaw);
        double s = Math.sin(yaw);
        return new Transform2D(x + c * inner.x - s * inner.y, y + s * inner.x + c * inner.y, yaw + inner.yaw);
    }

    /** The other direction: child←parent for this parent←child. */
    public Transform2D inverse() {
        double c = Math.cos(yaw);
        double s = Math.sin(yaw);
        return new Transform2D(-c * x - s * y, s * x - c * y, -yaw);
    }

    /** A point of the child frame in the parent frame: {x, y}. */
    public double[] apply(double px, double py) {
        double c = Math.cos(yaw);
        double s = Math.sin(yaw);
        return new double[] {x + c * px - s * py, y + s * px + c * py};
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(yaw);
    }
}
