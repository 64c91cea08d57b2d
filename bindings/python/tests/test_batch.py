"""Query.check_configurations, check_motion and check_motions on a generated
7-joint arm: the answers equal the single calls (set_joint_positions, then
collide / distance) for 1, 2 and 3 threads, self-collision adds folded
configurations whatever the thread count; motions equal a walk over their
samples; bad input raises with the argument named."""
import math
import threading
import unittest

import numpy as np

import octoprox

JOINTS = 7


def arm_urdf():
    """Links l0..l7, each a cylinder from 0.04 to 0.2 m along its z (so
    neighbours touch only when bent far), joints alternating z and y axes
    0.24 m apart."""
    links, joints = [], []
    for k in range(JOINTS + 1):
        links.append(
            f'<link name="l{k}"><collision><origin xyz="0 0 0.12"/><geometry>'
            f'<cylinder radius="0.035" length="0.16"/></geometry></collision></link>')
        if k > 0:
            axis = "0 0 1" if k % 2 else "0 1 0"
            joints.append(
                f'<joint name="j{k}" type="revolute"><parent link="l{k - 1}"/><child link="l{k}"/>'
                f'<origin xyz="0 0 {0.1 if k == 1 else 0.24}"/><axis xyz="{axis}"/>'
                f'<limit lower="-3.14" upper="3.14" effort="1" velocity="1"/></joint>')
    return '<robot name="arm">' + "".join(links + joints) + "</robot>"


def load_arm():
    return octoprox.LinkSet.from_urdf_string(arm_urdf())


def scatter_map(seed=7):
    rng = np.random.default_rng(seed)
    points = np.column_stack([rng.uniform(-1.1, 1.1, 90), rng.uniform(-1.1, 1.1, 90),
                              rng.uniform(0.15, 1.9, 90)])
    tree = octoprox.Octree(resolution=0.05)
    tree.insert_points(points, mode=octoprox.INSERT_ENDPOINTS)
    return tree


def random_rows(n, seed=11):
    return np.random.default_rng(seed).uniform(-3.1, 3.1, size=(n, JOINTS))


def single(query, tree, arm, q):
    arm.set_joint_positions(q)
    return bool(query.collide(tree, arm, max_contacts=0).collided)


class CheckConfigurations(unittest.TestCase):
    def setUp(self):
        self.arm, self.tree, self.rows = load_arm(), scatter_map(), random_rows(150)

    def test_equals_single_calls_for_every_thread_count(self):
        reference = octoprox.Query()
        expected = [single(reference, self.tree, self.arm, q) for q in self.rows]
        self.assertTrue(0 < sum(expected) < len(expected))
        for threads in (1, 2, 3):
            got = octoprox.Query().check_configurations(self.tree, self.arm, self.rows, threads=threads)
            self.assertEqual(got.dtype, np.bool_)
            self.assertEqual(got.tolist(), expected)

    def test_self_collision_adds_folded_configurations(self):
        world = octoprox.Query().check_configurations(self.tree, self.arm, self.rows)
        both = octoprox.Query().check_configurations(self.tree, self.arm, self.rows, self_collision=True)
        self.assertTrue(np.all(both >= world) and np.any(both > world))
        for threads in (2, 3):
            again = octoprox.Query().check_configurations(self.tree, self.arm, self.rows, threads=threads,
                                                          self_collision=True)
            self.assertEqual(again.tolist(), both.tolist())

    def test_distances_equal_distance_queries(self):
        reference = octoprox.Query()
        collided, distances = octoprox.Query().check_configurations(self.tree, self.arm, self.rows, threads=2,
                                                                    distance=True)
        for q, hit, d in zip(self.rows, collided, distances):
            self.arm.set_joint_positions(q)
            self.assertEqual(d, reference.distance(self.tree, self.arm).distance)
            self.assertEqual(hit, single(reference, self.tree, self.arm, q))

    def test_the_robot_does_not_move(self):
        before = self.arm.joint_positions.copy()
        octoprox.Query().check_configurations(self.tree, self.arm, self.rows[:10])
        self.assertEqual(self.arm.joint_positions.tolist(), before.tolist())

    def test_base_poses_one_or_per_row_and_strided_rows(self):
        wide = np.zeros((40, JOINTS + 2))
        wide[:, :JOINTS] = self.rows[:40]
        view = wide[:, :JOINTS]  # rows 9 doubles apart, read in place
        bases = np.zeros((40, 7))
        bases[:, 0] = np.linspace(-0.3, 0.3, 40)
        bases[:, 6] = 1.0
        query, reference = octoprox.Query(), octoprox.Query()
        per_row = query.check_configurations(self.tree, self.arm, view, base_pose=bases)
        shared = query.check_configurations(self.tree, self.arm, view, base_pose=(0.1, 0.0, 0.0))
        for i, q in enumerate(self.rows[:40]):
            self.arm.set_joint_positions(q, base_pose=bases[i])
            self.assertEqual(per_row[i], bool(reference.collide(self.tree, self.arm).collided))
            self.arm.set_joint_positions(q, base_pose=(0.1, 0.0, 0.0))
            self.assertEqual(shared[i], bool(reference.collide(self.tree, self.arm).collided))

    def test_no_rows_give_empty_answers(self):
        got = octoprox.Query().check_configurations(self.tree, self.arm, np.zeros((0, JOINTS)))
        self.assertEqual(got.shape, (0,))

    def test_threads_of_python_share_the_robot(self):
        expected = octoprox.Query().check_configurations(self.tree, self.arm, self.rows)
        answers = [None, None]

        def work(i):
            answers[i] = octoprox.Query().check_configurations(self.tree, self.arm, self.rows, threads=2)

        threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for answer in answers:
            self.assertEqual(answer.tolist(), expected.tolist())

    def test_bad_input_names_the_argument(self):
        query = octoprox.Query()
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            query.check_configurations(self.tree, self.arm, np.zeros((3, JOINTS - 1)))
        self.assertIn("joint_count", str(caught.exception))
        rows = self.rows[:3].copy()
        rows[1, 2] = math.nan
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            query.check_configurations(self.tree, self.arm, rows)
        self.assertIn("positions[row 1][joint 2]", str(caught.exception))
        with self.assertRaises(octoprox.InvalidArgumentError):
            query.check_configurations(self.tree, self.arm, self.rows[:3], base_pose=np.zeros((2, 7)))
        with self.assertRaises(TypeError):
            query.check_configurations(self.arm, self.tree, self.rows)
        plain = octoprox.LinkSet()
        with self.assertRaises(octoprox.UnsupportedError):
            query.check_configurations(self.tree, plain, np.zeros((1, 0)))


class CheckMotions(unittest.TestCase):
    def setUp(self):
        self.arm, self.tree = load_arm(), scatter_map()
        rng = np.random.default_rng(5)
        self.starts = random_rows(30, 3)
        self.goals = self.starts + rng.uniform(-0.4, 0.4, size=self.starts.shape)

    def test_first_collision_equals_a_walk_over_the_samples(self):
        query, reference = octoprox.Query(), octoprox.Query()
        for a, b in zip(self.starts, self.goals):
            result = query.check_motion(self.tree, self.arm, a, b, resolution=0.05)
            n = int(result.steps)
            self.assertEqual(n, max(1, math.ceil(np.max(np.abs(b - a)) / 0.05)))
            first = -1
            for i in range(n + 1):
                q = b if i == n else a + (i / n) * (b - a)
                if single(reference, self.tree, self.arm, q):
                    first = i
                    break
            self.assertEqual(result.collided, int(first >= 0))
            self.assertEqual(result.first_collision_fraction, -1.0 if first < 0 else first / n)

    def test_batch_equals_single_motions(self):
        query = octoprox.Query()
        for threads in (1, 2, 3):
            collided, fractions = query.check_motions(self.tree, self.arm, self.starts, self.goals,
                                                      resolution=0.05, threads=threads)
            for m, (a, b) in enumerate(zip(self.starts, self.goals)):
                result = query.check_motion(self.tree, self.arm, a, b, resolution=0.05)
                self.assertEqual(collided[m], bool(result.collided))
                self.assertEqual(fractions[m], result.first_collision_fraction)

    def test_swept_cost_gives_cost_boxes(self):
        query = octoprox.Query()
        result = query.check_motion(self.tree, self.arm, self.starts[0], self.goals[0], resolution=0.05,
                                    compute_cost=True)
        self.assertGreater(result.total_cost, 0.0)
        self.assertEqual(len(query.cost_boxes()), result.cost_box_count)

    def test_certified_is_free_only_when_a_dense_walk_is(self):
        query, reference = octoprox.Query(), octoprox.Query()
        collided, fractions = query.check_motions(self.tree, self.arm, self.starts[:8], self.goals[:8],
                                                  certified=True, threads=2)
        for m, (a, b) in enumerate(zip(self.starts[:8], self.goals[:8])):
            result = query.check_motion(self.tree, self.arm, a, b, certified=True, tolerance=1e-3)
            self.assertEqual(collided[m], bool(result.collided))
            self.assertEqual(fractions[m], result.first_collision_fraction)
            f = result.first_collision_fraction
            end = 2.0 if f < 0 else f - 1e-3
            for i in range(0, 1001):  # every 1e-3 of the motion before the bracket
                if i / 1000 >= end:
                    break
                self.assertFalse(single(reference, self.tree, self.arm, a + (i / 1000) * (b - a)))
            sampled = query.check_motion(self.tree, self.arm, a, b, resolution=0.05)
            if sampled.collided:
                self.assertTrue(result.collided)

    def test_certified_bad_tolerance(self):
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            octoprox.Query().check_motion(self.tree, self.arm, self.starts[0], self.goals[0], certified=True,
                                          tolerance=0.0)
        self.assertIn("request->tolerance", str(caught.exception))

    def test_bad_resolution(self):
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            octoprox.Query().check_motion(self.tree, self.arm, self.starts[0], self.goals[0], resolution=0.0)
        self.assertIn("request->resolution", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
