import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'atlas_bringup'

setup(
    name=package_name,
    version='0.3.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*launch.[pxy][yma]*')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Atlas Robotics Team',
    maintainer_email='robotics@example.com',
    description='Top-level bring-up of the Atlas mobile manipulator',
    license='Apache-2.0',
)
