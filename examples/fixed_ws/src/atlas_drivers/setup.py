import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'atlas_drivers'

setup(
    name=package_name,
    version='0.3.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*launch.[pxy][yma]*')),
        (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ],
    install_requires=['setuptools', 'pyserial'],
    zip_safe=True,
    maintainer='Atlas Robotics Team',
    maintainer_email='robotics@example.com',
    description='Sensor drivers of the Atlas robot',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'imu_node = atlas_drivers.imu_node:main',
        ],
    },
)
